using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Tests.Engines;

/// <summary>One full-state engine (two bridges) shared by every test that runs Q#, started once.</summary>
public sealed class FullStateFixture : IDisposable
{
    public FullStateEngine Engine { get; } = new(new BridgePool(2));

    public void Dispose() => Engine.Dispose();
}

/// <summary>Tests that share the fixture's two bridges run one class at a time: a bridge serves one request at a time.</summary>
[CollectionDefinition(Name)]
public sealed class QSharpCollection : ICollectionFixture<FullStateFixture>
{
    public const string Name = "Q#";
}
