using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Cluster;

/// <summary>The bridges a Q# engine runs on: a cluster's workers, or this machine's Node processes.</summary>
public static class ClusterBridges
{
    /// <summary>
    /// One bridge per worker bridge of the cluster <paramref name="configPath"/> names, or <paramref name="localWorkers"/>
    /// local bridges without one. <paramref name="clock"/> measures the cluster's chunk time limit (default: the system's).
    /// </summary>
    public static BridgePool Start(string? configPath, int localWorkers, TimeProvider? clock = null)
    {
        if (configPath is null) return new BridgePool(localWorkers);
        var transport = ClusterTransport.Connect(ClusterConfig.Load(configPath), clock);
        return new BridgePool(transport, transport.Capacity, transport);
    }
}
