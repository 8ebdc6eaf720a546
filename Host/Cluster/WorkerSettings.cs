namespace QuantumRayTracing.Cluster;

/// <summary>Everything one worker of a cluster needs (<see cref="WorkerRun"/>): what `qrt worker` reads from its options.</summary>
/// <param name="ClusterFile">The cluster file (docs/cluster.md).</param>
/// <param name="Workers">Node bridge processes running Q# chunks in parallel.</param>
/// <param name="SiloPort">Port the workers talk to each other on; null: the cluster file's primary port.</param>
/// <param name="GatewayPort">Port renders connect to; null: the first of the cluster file's gateways.</param>
/// <param name="Advertise">Redis membership: the host name other machines reach this worker at; null: this machine's.</param>
/// <param name="LoadEverySeconds">Seconds between load lines; 0 for none.</param>
public sealed record WorkerSettings(string ClusterFile, int Workers, int? SiloPort, int? GatewayPort, string? Advertise, int LoadEverySeconds);
