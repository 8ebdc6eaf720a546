using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Cluster;

/// <summary>The bridges a Q# engine runs on: a cluster's workers, or this machine's Node processes.</summary>
public static class ClusterBridges
{
    /// <summary>One bridge per worker bridge of the cluster <paramref name="configPath"/> names, or <paramref name="localWorkers"/> local bridges without one.</summary>
    public static BridgePool Start(string? configPath, int localWorkers)
    {
        if (configPath is null) return new BridgePool(localWorkers);
        var transport = ClusterTransport.Connect(ClusterConfig.Load(configPath));
        return new BridgePool(transport, transport.Capacity, transport);
    }
}
