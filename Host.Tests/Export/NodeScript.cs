using System.Collections.Concurrent;
using System.Diagnostics;
using System.Text;
using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// Runs one of Quantum/'s check scripts and returns its JSON reply. Each script runs as a server (its --serve
/// mode, Quantum/check-serve.mjs) that checks one file per request: loading quantum-circuit or the QDK takes
/// about a second, the check of a small file a fraction of that. Idle servers are kept for the next request
/// (one more is started when all are busy, so tests never wait for each other); they end with the test run.
/// </summary>
internal static class NodeScript
{
    private static readonly ConcurrentDictionary<string, ConcurrentBag<Server>> Idle = new();

    private static readonly ConcurrentBag<Server> All = [];

    static NodeScript() => AppDomain.CurrentDomain.ProcessExit += (_, _) =>
    {
        foreach (var server in All) server.Dispose();
    };

    public static JsonNode Run(string script, params string[] arguments)
    {
        var idle = Idle.GetOrAdd(script, _ => []);
        if (!idle.TryTake(out var server))
        {
            server = new Server(script);
            All.Add(server);
        }
        JsonObject reply;
        try
        {
            reply = server.Ask(arguments);
        }
        catch
        {
            server.Dispose();
            throw;
        }
        idle.Add(server);
        Assert.True(reply["ok"]!.GetValue<bool>(), $"{script} failed: {reply["error"]}");
        return reply["result"]!;
    }

    /// <summary>One script running with --serve: a JSON array of arguments per line in, one reply per line out.</summary>
    private sealed class Server : IDisposable
    {
        private readonly string _script;
        private readonly Process _node;
        private readonly StringBuilder _stderr = new();

        public Server(string script)
        {
            _script = script;
            var start = new ProcessStartInfo("node")
            {
                RedirectStandardInput = true,
                RedirectStandardOutput = true,
                RedirectStandardError = true,
                WorkingDirectory = QuantumProject.Directory,
                StandardOutputEncoding = Encoding.UTF8,
            };
            start.ArgumentList.Add(Path.Combine(QuantumProject.Directory, script));
            start.ArgumentList.Add("--serve");
            _node = Process.Start(start)!;
            // quantum-circuit warns on stderr: drained, so that the pipe never fills.
            _node.ErrorDataReceived += (_, e) =>
            {
                lock (_stderr) _stderr.AppendLine(e.Data);
            };
            _node.BeginErrorReadLine();
        }

        public JsonObject Ask(string[] arguments)
        {
            _node.StandardInput.WriteLine(new JsonArray([.. arguments.Select(a => (JsonNode?)a)]).ToJsonString());
            _node.StandardInput.Flush();
            var line = _node.StandardOutput.ReadLine();
            if (line is null)
            {
                _node.WaitForExit();
                lock (_stderr) throw new InvalidOperationException($"{_script} ended (exit code {_node.ExitCode}): {_stderr}");
            }
            return JsonNode.Parse(line)!.AsObject();
        }

        public void Dispose()
        {
            try
            {
                if (!_node.HasExited) _node.Kill();
            }
            catch (InvalidOperationException)
            {
                // Already gone.
            }
        }
    }
}
