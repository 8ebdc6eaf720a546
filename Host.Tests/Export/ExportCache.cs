using System.Collections.Concurrent;
using System.Security.Cryptography;
using System.Text;
using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Export;
using QuantumRayTracing.Output;
using QuantumRayTracing.Tests.Cli;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// The exports the checks read, each made once per test run: `qrt export` through the command line (as a user
/// runs it) or <see cref="CircuitExporter"/>, on one bridge kept running (<see cref="ExportRun.SharedBridge"/>).
/// A bridge's start-up and first requests cost more than a small circuit's export, and several tests check
/// the same file. The bridge sends each distinct request once: a circuit's export in another format asks the QDK
/// the same (its QIR and distribution), and each format is written from that reply. The files are the cache's: a
/// test that changes one writes its copy elsewhere.
/// </summary>
internal static class ExportCache
{
    private static readonly string Folder = Directory.CreateTempSubdirectory("qrt-export-cache-").FullName;

    private static readonly ConcurrentDictionary<string, Lazy<string>> Made = new();

    private static readonly Lock BridgeGate = new();

    private static readonly QSharpBridge Local = new();

    private static readonly QSharpBridge Bridge = new(new OnceEach(Local));

    static ExportCache() => AppDomain.CurrentDomain.ProcessExit += (_, _) =>
    {
        Local.Dispose();
        Directory.Delete(Folder, recursive: true);
    };

    /// <summary>The file `qrt <paramref name="arguments"/> -o FILE` writes (the command must succeed).</summary>
    public static string File(params string[] arguments) => Once("cli\n" + string.Join('\n', arguments), () =>
    {
        var file = Path.Combine(Folder, $"{Guid.NewGuid():N}.txt");
        var (code, error) = RunOnTheSharedBridge([.. arguments, "-o", file]);
        Assert.True(code == 0, error);
        return file;
    });

    /// <summary>`qrt <paramref name="arguments"/>` with console capture, its export (if any) on the shared bridge: exit code and standard error.</summary>
    private static (int Code, string Error) RunOnTheSharedBridge(params string[] arguments)
    {
        lock (BridgeGate)
        {
            ExportRun.SharedBridge.Value = Bridge;
            try
            {
                return ConsoleCapture.Run(arguments);
            }
            finally
            {
                ExportRun.SharedBridge.Value = null;
            }
        }
    }

    /// <summary>A file holding <paramref name="json"/> (a scene), named by its content so equal scenes share exports.</summary>
    public static string Scene(string json)
    {
        var path = Path.Combine(Folder, $"scene-{Convert.ToHexString(SHA256.HashData(Encoding.UTF8.GetBytes(json)))[..16]}.json");
        return Once("scene\n" + path, () =>
        {
            System.IO.File.WriteAllText(path, json);
            return path;
        });
    }

    /// <summary><see cref="CircuitExporter.Export"/> of <paramref name="subject"/>: the text.</summary>
    public static string Export(ExportSubject subject, ExportFormat format)
    {
        var key = string.Join('\n', ["export", format.ToString(), subject.Title, .. subject.Description, subject.Apply, $"{subject.RegisterQubits} {subject.RegisterName} {subject.UnmeasuredQubits}"]);
        return Once(key, () =>
        {
            lock (BridgeGate) return CircuitExporter.Export(Bridge, subject, format);
        });
    }

    /// <summary>The local bridge's replies, each distinct request sent once (used under <see cref="BridgeGate"/>).</summary>
    private sealed class OnceEach(QSharpBridge bridge) : IBridgeTransport
    {
        private readonly Dictionary<string, JsonNode> _replies = [];

        public JsonNode Send(JsonObject request)
        {
            var key = request.ToJsonString();
            if (!_replies.TryGetValue(key, out var reply)) _replies[key] = reply = bridge.Send(request);
            return reply.DeepClone();
        }

        public RunPlace Place => RunPlace.LocalBridges(1);
    }

    /// <summary>What <paramref name="make"/> returns for <paramref name="key"/>, made by the first caller.</summary>
    private static string Once(string key, Func<string> make) => Made.GetOrAdd(key, _ => new Lazy<string>(make)).Value;
}
