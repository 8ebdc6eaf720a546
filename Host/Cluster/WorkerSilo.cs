using System.Net;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Orleans.Configuration;
using StackExchange.Redis;

namespace QuantumRayTracing.Cluster;

/// <summary>Builds the Orleans silo of one worker: its membership, its ports and the grain that serves chunks.</summary>
public static class WorkerSilo
{
    /// <summary>Name shared by every cluster of this program (Orleans' service id).</summary>
    public const string ServiceId = "qrt";

    /// <summary>
    /// A silo serving chunks on <paramref name="executor"/>. <paramref name="advertise"/> is the address other
    /// machines reach it at under Redis membership (default: this host name's address); Orleans logs from
    /// <paramref name="logFrom"/> up.
    /// </summary>
    public static IHost Build(ClusterConfig config, int siloPort, int gatewayPort, IChunkExecutor executor, string? advertise = null, LogLevel logFrom = LogLevel.Warning)
    {
        var builder = Host.CreateApplicationBuilder(new HostApplicationBuilderSettings { Args = [], ContentRootPath = AppContext.BaseDirectory });
        // Orleans speaks up only for warnings; the worker prints its own readiness and load lines.
        builder.Logging.ClearProviders();
        builder.Logging.AddSimpleConsole(o => o.SingleLine = true);
        builder.Logging.SetMinimumLevel(logFrom);
        builder.Logging.AddFilter("Orleans.Runtime.Silo", LogLevel.Error); // its start-up notes on server GC
        builder.Logging.AddFilter("Orleans.Runtime.Watchdog", LogLevel.Error); // its first check reads the time since boot as a stall
        builder.Services.AddSingleton(executor);
        builder.Services.AddSingleton<WorkerStatistics>();
        builder.UseOrleans(silo =>
        {
            silo.Configure<ClusterOptions>(o => (o.ClusterId, o.ServiceId) = (config.ClusterId, ServiceId));
            if (config.Clustering == ClusteringKind.Localhost)
            {
                silo.UseLocalhostClustering(siloPort, gatewayPort, new IPEndPoint(IPAddress.Loopback, config.PrimaryPort), ServiceId, config.ClusterId);
            }
            else
            {
                silo.UseRedisClustering(o => o.ConfigurationOptions = ConfigurationOptions.Parse(config.Redis!));
                silo.ConfigureEndpoints(advertise ?? Dns.GetHostName(), siloPort, gatewayPort, System.Net.Sockets.AddressFamily.InterNetwork, listenOnAnyHostAddress: true);
            }
            silo.AddPlacementDirector<SiloKeyedPlacementStrategy, SiloKeyedPlacementDirector>();
            if (config.Certificate is { } file)
            {
                var certificate = ClusterCertificate.Load(config.Path, file);
                silo.UseTls(certificate, o => ClusterCertificate.Configure(o, certificate));
            }
        });
        return builder.Build();
    }
}
