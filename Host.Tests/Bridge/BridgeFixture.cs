using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Tests.Bridge;

/// <summary>One bridge a test class's requests share (a start-up compiles the Q# library); tests that kill or break a bridge start their own.</summary>
public sealed class BridgeFixture : IDisposable
{
    public QSharpBridge Bridge { get; } = new();

    public void Dispose() => Bridge.Dispose();
}
