using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Orleans.Runtime;

namespace QuantumRayTracing.Cluster;

/// <summary>
/// One worker of a cluster: an Orleans silo running the chunks renders send it (Q# chunks on its own Node bridges, image
/// parts in this process), until SIGINT or SIGTERM stops it and its bridges. It says when it is ready, its load now and then, and what it served.
/// </summary>
public static class WorkerRun
{
    public static void Run(WorkerSettings settings, Action<string> say)
    {
        var config = ClusterConfig.Load(settings.ClusterFile);
        var siloPort = settings.SiloPort ?? config.PrimaryPort;
        var gatewayPort = settings.GatewayPort ?? config.Gateways[0];
        using var bridges = new WorkerBridges(settings.Workers);
        say($"starting {bridges.Capacity} bridge{(bridges.Capacity == 1 ? "" : "s")} (loading the QDK, compiling the Q# sources)");
        var qsharp = bridges.Start();
        using var host = WorkerSilo.Build(config, siloPort, gatewayPort, new WorkerExecutor(bridges), settings.Advertise);
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
        say($"worker ready: cluster '{config.ClusterId}' ({config.Clustering.ToString().ToLowerInvariant()} membership, {config.Path}), silo {silo}, gateway port {gatewayPort}, {bridges.Capacity} bridges, qsharp-lang {qsharp}, {(config.Certificate is null ? "plain TCP: any process that reaches these ports can send work (docs/cluster.md)" : $"mutual TLS: only holders of {System.IO.Path.GetFileName(config.Certificate)}")}");

        var statistics = host.Services.GetRequiredService<WorkerStatistics>();
        var lifetime = host.Services.GetRequiredService<IHostApplicationLifetime>();
        var every = settings.LoadEverySeconds;
        var last = (-1, -1L);
        while (every > 0 && !lifetime.ApplicationStopping.WaitHandle.WaitOne(TimeSpan.FromSeconds(every)))
        {
            var now = (statistics.Busy, statistics.Served);
            if (now != last) say($"load: {now.Busy} chunks running or queued on {bridges.Capacity} bridges, {now.Served} served");
            last = now;
        }
        host.WaitForShutdown();
        say($"worker stopped: {statistics.Served} chunks served; bridges closed");
    }
}
