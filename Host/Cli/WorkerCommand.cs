using System.CommandLine;
using QuantumRayTracing.Cluster;

namespace QuantumRayTracing.Cli;

/// <summary>`worker`: options → <see cref="WorkerSettings"/> → <see cref="WorkerRun"/>, a worker of a cluster serving Q# chunks on this machine's bridges.</summary>
public sealed class WorkerCommand : Command
{
    private readonly Option<FileInfo?> _cluster = CommonOptions.Cluster("The cluster file (JSON: clusterId, clustering localhost|redis, primaryPort, gateways, redis, chunkTimeoutSeconds, certificate; docs/cluster.md). Default: none; a worker needs one.", required: true);

    private readonly Option<int> _workers = CommonOptions.Workers("Node bridge processes running Q# chunks in parallel. Default: the core count.");

    private readonly Option<int?> _siloPort = Port("--silo-port", "Port the workers talk to each other on. Default: the cluster file's primaryPort (the first worker on a machine); each further worker on one machine needs its own.");

    private readonly Option<int?> _gatewayPort = Port("--gateway-port", "Port renders connect to. Default: the first of the cluster file's gateways; each further worker on one machine needs its own (list it in gateways under localhost membership).");

    private readonly Option<string?> _advertise = new("--advertise")
    {
        Description = "Redis membership: the host name or address other machines reach this worker at. Default: this machine's host name.",
        HelpName = "host",
    };

    private readonly Option<int> _loadEvery = new Option<int>("--load-every")
    {
        Description = "Seconds between load lines (bridges busy, chunks served); 0 for none.",
        DefaultValueFactory = _ => 10,
        HelpName = "seconds",
    }.Between(0, 86_400);

    private static Option<int?> Port(string name, string description) => new Option<int?>(name) { Description = description, HelpName = "port" }.Between(1, 65535);

    public WorkerCommand() : base("worker", "Serve Q# chunks of renders on this machine's bridges, as a worker of a cluster (docs/cluster.md).")
    {
        this.AddOptions(_cluster, _workers, _siloPort, _gatewayPort, _advertise, _loadEvery);
        SetAction(parse =>
        {
            WorkerRun.Run(new WorkerSettings(parse.GetValue(_cluster)!.FullName, parse.GetValue(_workers), parse.GetValue(_siloPort),
                parse.GetValue(_gatewayPort), parse.GetValue(_advertise), parse.GetValue(_loadEvery)), Console.WriteLine);
            return ExitCodes.Success;
        });
    }
}
