using System.CommandLine;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Orleans.Runtime;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cluster;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `worker`: joins a cluster as an Orleans silo and runs the chunks renders send it on its own Node bridges,
/// until SIGINT or SIGTERM stops it and its bridges.
/// </summary>
public sealed class WorkerCommand : Command
{
    private readonly Option<FileInfo> _cluster = new("--cluster")
    {
        Description = "The cluster file (JSON: clusterId, clustering localhost|redis, primaryPort, gateways, redis, chunkTimeoutSeconds; docs/cluster.md). Default: none; a worker needs one.",
        HelpName = "file",
        Required = true,
    };

    private readonly Option<int> _workers = new("--workers")
    {
        Description = "Node bridge processes running Q# chunks in parallel. Default: the core count.",
        DefaultValueFactory = _ => BridgePool.DefaultWorkers,
    };

    private readonly Option<int?> _siloPort = new("--silo-port")
    {
        Description = "Port the workers talk to each other on. Default: the cluster file's primaryPort (the first worker on a machine); each further worker on one machine needs its own.",
        HelpName = "port",
    };

    private readonly Option<int?> _gatewayPort = new("--gateway-port")
    {
        Description = "Port renders connect to. Default: the first of the cluster file's gateways; each further worker on one machine needs its own (list it in gateways under localhost membership).",
        HelpName = "port",
    };

    private readonly Option<string?> _advertise = new("--advertise")
    {
        Description = "Redis membership: the host name or address other machines reach this worker at. Default: this machine's host name.",
        HelpName = "host",
    };

    private readonly Option<int> _loadEvery = new("--load-every")
    {
        Description = "Seconds between load lines (bridges busy, chunks served); 0 for none.",
        DefaultValueFactory = _ => 10,
        HelpName = "seconds",
    };

    public WorkerCommand() : base("worker", "Serve Q# chunks of renders on this machine's bridges, as a worker of a cluster (docs/cluster.md).")
    {
        Options.Add(_cluster);
        Options.Add(_workers);
        Options.Add(_siloPort);
        Options.Add(_gatewayPort);
        Options.Add(_advertise);
        Options.Add(_loadEvery);
        _workers.AtLeast(1);
        _siloPort.Between(1, 65535);
        _gatewayPort.Between(1, 65535);
        _loadEvery.Between(0, 86_400);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var config = ClusterConfig.Load(parse.GetValue(_cluster)!.FullName);
        var siloPort = parse.GetValue(_siloPort) ?? config.PrimaryPort;
        var gatewayPort = parse.GetValue(_gatewayPort) ?? config.Gateways[0];
        using var bridges = new WorkerBridges(parse.GetValue(_workers));
        Console.WriteLine($"starting {bridges.Capacity} bridge{(bridges.Capacity == 1 ? "" : "s")} (loading the QDK, compiling the Q# sources)");
        var qsharp = bridges.Start();
        using var host = WorkerSilo.Build(config, siloPort, gatewayPort, bridges, parse.GetValue(_advertise));
        try
        {
            host.Start();
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            var where = config.Clustering == ClusteringKind.Localhost ? $"silo port {siloPort}, gateway port {gatewayPort}" : $"Redis {config.Redis}";
            throw new ClusterException($"{config.Path}: this worker could not join cluster '{config.ClusterId}' ({where}): {e.Message.Split('\n')[0].TrimEnd('\r')}", e);
        }
        var silo = host.Services.GetRequiredService<ILocalSiloDetails>().SiloAddress;
        Console.WriteLine($"worker ready: cluster '{config.ClusterId}' ({config.Clustering.ToString().ToLowerInvariant()} membership, {config.Path}), silo {silo}, gateway port {gatewayPort}, {bridges.Capacity} bridges, qsharp-lang {qsharp}");

        var statistics = host.Services.GetRequiredService<WorkerStatistics>();
        var lifetime = host.Services.GetRequiredService<IHostApplicationLifetime>();
        var every = parse.GetValue(_loadEvery);
        var last = (-1, -1L);
        while (every > 0 && !lifetime.ApplicationStopping.WaitHandle.WaitOne(TimeSpan.FromSeconds(every)))
        {
            var now = (statistics.Busy, statistics.Served);
            if (now != last) Console.WriteLine($"load: {now.Busy} chunks running or queued on {bridges.Capacity} bridges, {now.Served} served");
            last = now;
        }
        host.WaitForShutdown();
        Console.WriteLine($"worker stopped: {statistics.Served} chunks served; bridges closed");
        return 0;
    }
}
