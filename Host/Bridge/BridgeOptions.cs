namespace QuantumRayTracing.Bridge;

/// <summary>How to start a bridge process and how long to wait for it.</summary>
public sealed record BridgeOptions
{
    /// <summary>The Node.js executable.</summary>
    public string Node { get; init; } = "node";

    /// <summary>The bridge script; by default Quantum/bridge.mjs.</summary>
    public string Script { get; init; } = QuantumProject.BridgeScript;

    /// <summary>Time to load the QDK and compile the Q# sources.</summary>
    public TimeSpan StartTimeout { get; init; } = TimeSpan.FromSeconds(60);

    /// <summary>Time limit of one request.</summary>
    public TimeSpan RequestTimeout { get; init; } = TimeSpan.FromMinutes(10);
}
