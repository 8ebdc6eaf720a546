using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Cluster;

/// <summary>The cluster could not run a chunk: no worker reachable, or every worker failed it.</summary>
public sealed class ClusterException(string message, Exception? inner = null) : BridgeException(message, inner);
