using System.Net;
using Garnet;
using Garnet.server;
using Microsoft.Extensions.Logging.Abstractions;

namespace QuantumRayTracing.Tests.Cluster;

/// <summary>
/// A Redis-compatible server (Garnet) inside the test process, on a free loopback port, in memory only, so the
/// Redis membership tests need no redis-server on the machine. Orleans writes membership through EVAL scripts,
/// so Lua is on, each script run as a transaction for Orleans' compare-and-swap updates.
/// </summary>
public sealed class InProcessRedis : IDisposable
{
    private readonly GarnetServer _server;

    public InProcessRedis()
    {
        Port = TestCluster.FreePorts(1)[0];
        var options = new GarnetServerOptions
        {
            EndPoints = [new IPEndPoint(IPAddress.Loopback, Port)],
            EnableLua = true,
            LuaOptions = new LuaOptions(NullLogger.Instance),
            LuaTransactionMode = true,
            QuietMode = true,
        };
        _server = new GarnetServer(options, NullLoggerFactory.Instance);
        _server.Start();
    }

    public int Port { get; }

    /// <summary>The StackExchange.Redis connection string a cluster file names.</summary>
    public string Address => $"127.0.0.1:{Port}";

    public void Dispose() => _server.Dispose();
}
