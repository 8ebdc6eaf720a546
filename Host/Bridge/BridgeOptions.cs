namespace QuantumRayTracing.Bridge;

/// <summary>How to start a bridge process and how long to wait for it.</summary>
public sealed record BridgeOptions
{
    /// <summary>Environment variable naming the Node.js executable when it is not <c>node</c> on the PATH.</summary>
    public const string NodeVariable = "QRT_NODE";

    /// <summary>The Node.js executable: <see cref="NodeVariable"/> if set, else <c>node</c>.</summary>
    public string Node { get; init; } = Environment.GetEnvironmentVariable(NodeVariable) is { Length: > 0 } node ? node : "node";

    /// <summary>The bridge script; by default Quantum/bridge.mjs.</summary>
    public string Script { get; init; } = QuantumProject.BridgeScript;

    /// <summary>Time to load the QDK and compile the Q# sources.</summary>
    public TimeSpan StartTimeout { get; init; } = TimeSpan.FromSeconds(60);

    /// <summary>Time limit of one request.</summary>
    public TimeSpan RequestTimeout { get; init; } = TimeSpan.FromMinutes(10);
}
