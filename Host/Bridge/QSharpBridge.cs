using System.Collections.Concurrent;
using System.ComponentModel;
using System.Diagnostics;
using System.Text;
using System.Text.Json;
using System.Text.Json.Nodes;
using QuantumRayTracing.Noise;

namespace QuantumRayTracing.Bridge;

/// <summary>
/// Owns one Node bridge process (Quantum/bridge.mjs): starts it, sends one JSON request per line
/// and reads the reply, enforces the time limit by killing the process, restarts a bridge that died
/// once per request, and turns every failure into a <see cref="BridgeException"/> or
/// <see cref="QSharpException"/>. Not thread-safe: one bridge serves one worker.
/// </summary>
public sealed class QSharpBridge(BridgeOptions options) : IDisposable
{
    private const int StderrTailLength = 4000;

    private Process? _process;
    private StringBuilder _stderr = new();
    private long _nextId;

    /// <summary>
    /// Keep a disposed bridge's Node process, its Q# sources compiled, for the next bridge started with the same options,
    /// instead of stopping it: a process that runs many short commands one after another (the test suite) then compiles the
    /// sources a few times, not once per bridge. A process that timed out, died or failed to start is never kept. Off by default.
    /// </summary>
    public static bool ReuseProcesses { get; set; }

    /// <summary>At most this many idle processes are kept per set of options; more are stopped.</summary>
    private const int MaxIdleProcesses = 4;

    private static readonly ConcurrentDictionary<string, ConcurrentBag<(Process Process, StringBuilder Stderr, string? Version)>> Idle = new();

    static QSharpBridge() => AppDomain.CurrentDomain.ProcessExit += (_, _) =>
    {
        foreach (var bag in Idle.Values)
            while (bag.TryTake(out var idle)) Kill(idle.Process);
    };

    private string IdleKey => options.Node + "\n" + options.Script;

    public QSharpBridge() : this(new BridgeOptions()) { }

    private readonly IBridgeTransport? _remote;

    /// <summary>A bridge whose requests <paramref name="remote"/> serves (a cluster's workers) instead of a local Node process.</summary>
    public QSharpBridge(IBridgeTransport remote) : this(new BridgeOptions()) => _remote = remote;

    private int _starts;

    /// <summary>How many times the bridge was started again after its process ended (crash, kill, time-out).</summary>
    public int Restarts => Math.Max(0, _starts - 1);

    /// <summary>Process id of the running bridge, or null.</summary>
    public int? ProcessId => _process is { HasExited: false } p ? p.Id : null;

    /// <summary>The qsharp-lang version the bridge reported when it started.</summary>
    public string? QSharpVersion { get; private set; }

    /// <summary>
    /// Runs a Q# expression for <paramref name="shots"/> shots; one Q# value (as the QDK prints it) per shot.
    /// A <paramref name="noise"/> model other than the ideal one runs it on the noisy simulator.
    /// </summary>
    public IReadOnlyList<string> Run(string expression, int shots = 1, TimeSpan? timeout = null, NoiseModel? noise = null)
    {
        var request = new JsonObject { ["method"] = "run", ["expr"] = expression, ["shots"] = shots };
        if (noise is { IsNoiseless: false })
        {
            request["noise"] = new JsonArray(noise.Px, noise.Py, noise.Pz);
            request["qubitLoss"] = noise.QubitLoss;
        }
        var result = Send(request, timeout);
        return result.AsArray().Select(v => v!.GetValue<string>()).ToArray();
    }

    /// <summary>Asks the Resource Estimator about a Q# expression; one result object per parameter set.</summary>
    public JsonArray Estimate(string expression, JsonArray? parameters = null, TimeSpan? timeout = null) =>
        Send(new JsonObject { ["method"] = "estimate", ["expr"] = expression, ["params"] = parameters ?? [new JsonObject()] }, timeout).AsArray();

    /// <summary>
    /// The circuit the QDK extracts from a Q# expression (getCircuit, by simulating it once), summarised
    /// by the bridge: qubits, gates by kind, measurements, resets and depth (Quantum/circuit-summary.mjs).
    /// A circuit of more than <paramref name="maxOperations"/> operations is refused, not truncated. With
    /// <paramref name="exposure"/> the summary also holds the noise exposure of every location (Quantum/noise-exposure.mjs)
    /// and, given <paramref name="marked"/> (the search's marked indices), its graded harm (Quantum/noise-harm.mjs, far slower),
    /// over every location or, with <paramref name="sampling"/>, a random share of them seeded as it says.
    /// </summary>
    public JsonObject Circuit(string expression, int? maxOperations = null, TimeSpan? timeout = null, bool exposure = false, IReadOnlyList<int>? marked = null,
        (double Fraction, uint Seed)? sampling = null)
    {
        var request = new JsonObject { ["method"] = "circuit", ["expr"] = expression };
        if (exposure) request["exposure"] = true;
        if (marked is not null)
        {
            request["harm"] = true;
            request["marked"] = new JsonArray([.. marked.Select(i => (JsonNode?)i)]);
            if (sampling is var (fraction, seed))
            {
                request["harmFraction"] = fraction;
                request["harmSeed"] = seed;
            }
        }
        if (maxOperations is { } limit) request["maxOperations"] = limit;
        return Send(request, timeout).AsObject();
    }

    /// <summary>The bridge's qsharp-lang and Node versions.</summary>
    public JsonObject Version() => Send(new JsonObject { ["method"] = "version" }).AsObject();

    /// <summary>Requests sent so far (each retry counted once more).</summary>
    public long Requests { get; private set; }

    /// <summary>Wall time spent waiting for replies, start-ups excluded: the time the QDK spent on the requests plus their transport.</summary>
    public TimeSpan RequestTime { get; private set; }

    /// <summary>Sends one request and returns its result; restarts a dead bridge and retries once.</summary>
    public JsonNode Send(JsonObject request, TimeSpan? timeout = null)
    {
        if (_remote is not null) return _remote.Send(request);
        var limit = timeout ?? options.RequestTimeout;
        try
        {
            return SendOnce(request, limit);
        }
        catch (BridgeDiedException first)
        {
            try
            {
                return SendOnce(request, limit);
            }
            catch (BridgeDiedException second)
            {
                throw new BridgeException(
                    $"the Node process running the Q# simulator crashed twice on one request ({first.Message}; then {second.Message}), as it does when a state outgrows its 4 GiB WebAssembly heap or Node.js is broken{StderrTail()}");
            }
        }
    }

    private JsonNode SendOnce(JsonObject request, TimeSpan timeout)
    {
        var process = EnsureStarted();
        var clock = Stopwatch.StartNew();
        var id = ++_nextId;
        request = (JsonObject)request.DeepClone();
        request["id"] = id;
        try
        {
            process.StandardInput.WriteLine(request.ToJsonString());
            process.StandardInput.Flush();
        }
        catch (IOException e)
        {
            Stop();
            throw new BridgeDiedException($"writing the request failed: {e.Message}");
        }

        var line = ReadLine(process, timeout, $"request {request["method"]}");
        Requests++;
        RequestTime += clock.Elapsed;
        var reply = ParseReply(line);
        if (reply["ok"]?.GetValue<bool>() == true)
            return reply["result"] ?? throw new BridgeException($"the Q# bridge replied without a result: {line}");
        throw ErrorFrom(reply["error"]);
    }

    private Process EnsureStarted()
    {
        if (_process is { HasExited: false }) return _process;
        Stop();
        if (ReuseProcesses && Idle.TryGetValue(IdleKey, out var idle))
            while (idle.TryTake(out var kept))
            {
                if (kept.Process.HasExited)
                {
                    kept.Process.Dispose();
                    continue;
                }
                (_process, _stderr, QSharpVersion) = kept;
                lock (_stderr) _stderr.Clear();
                _starts++;
                return _process;
            }
        var start = new ProcessStartInfo(options.Node)
        {
            WorkingDirectory = Path.GetDirectoryName(options.Script)!,
            RedirectStandardInput = true,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
            StandardOutputEncoding = Encoding.UTF8,
            StandardErrorEncoding = Encoding.UTF8,
        };
        start.ArgumentList.Add(options.Script);
        Process process;
        try
        {
            process = Process.Start(start) ?? throw new BridgeException($"could not start '{options.Node}'");
        }
        catch (Win32Exception e)
        {
            throw new BridgeException(
                $"could not start Node.js ('{options.Node}'): {e.Message}. Node.js 20 or later runs the Q# simulator: install it (README.md, Prerequisites) or set {BridgeOptions.NodeVariable} to its path.", e);
        }
        _starts++;
        // The process's own stderr buffer: it stays with the process if the process is kept for another bridge.
        var stderr = _stderr = new StringBuilder();
        process.ErrorDataReceived += (_, e) =>
        {
            if (e.Data is null) return;
            lock (stderr)
            {
                stderr.AppendLine(e.Data);
                if (stderr.Length > 4 * StderrTailLength) stderr.Remove(0, stderr.Length - StderrTailLength);
            }
        };
        process.BeginErrorReadLine();
        _process = process;

        var ready = ParseReply(ReadLine(process, options.StartTimeout, "start-up"));
        if (ready["ready"]?.GetValue<bool>() != true)
        {
            Stop();
            var message = ready["error"]?["message"]?.GetValue<string>() ?? ready.ToJsonString();
            throw new QSharpException($"the Q# sources do not compile:{Environment.NewLine}{message}", "compile", null, null);
        }
        QSharpVersion = ready["qsharp"]?.GetValue<string>();
        var pinned = QuantumProject.PinnedQSharpVersion(options.Script);
        if (pinned is not null && QSharpVersion != pinned)
        {
            Stop();
            throw new BridgeException(
                $"the Q# bridge runs qsharp-lang {QSharpVersion}, but Quantum/package.json pins {pinned}; run 'dotnet build' to reinstall the Node packages");
        }
        return process;
    }

    private string ReadLine(Process process, TimeSpan timeout, string what)
    {
        var read = process.StandardOutput.ReadLineAsync();
        if (!read.Wait(timeout))
        {
            Stop();
            throw new BridgeTimeoutException(
                $"the Q# bridge did not answer {what} within {timeout.TotalSeconds:0.###} s; it was stopped and restarts on next use");
        }
        if (read.Result is { } line) return line;
        if (process.WaitForExit(2000)) process.WaitForExit(); // also drains stderr
        var code = process.HasExited ? process.ExitCode.ToString() : "unknown";
        Stop();
        throw new BridgeDiedException($"the bridge exited (code {code}) during {what}");
    }

    private static JsonObject ParseReply(string line)
    {
        try
        {
            return JsonNode.Parse(line) as JsonObject ?? throw new BridgeException($"the Q# bridge sent a non-object line: {line}");
        }
        catch (JsonException e)
        {
            throw new BridgeException($"the Q# bridge sent a line that is not JSON: {line}", e);
        }
    }

    private static Exception ErrorFrom(JsonNode? error)
    {
        var kind = error?["kind"]?.GetValue<string>();
        var message = error?["message"]?.GetValue<string>() ?? "(no message)";
        return kind switch
        {
            "qsharp" => new QSharpException(
                message, error?["code"]?.GetValue<string>(), error?["location"]?.GetValue<string>(), error?["stack"]?.GetValue<string>()),
            "request" => new BridgeRequestException($"the Q# bridge rejected the request: {message}"),
            _ => new BridgeException($"the Q# bridge failed: {message}"),
        };
    }

    private string StderrTail()
    {
        lock (_stderr)
        {
            var text = _stderr.ToString().Trim();
            if (text.Length == 0) return "";
            if (text.Length > StderrTailLength) text = text[^StderrTailLength..];
            return $"{Environment.NewLine}bridge stderr:{Environment.NewLine}{text}";
        }
    }

    private void Stop()
    {
        if (_process is null) return;
        Kill(_process);
        _process = null;
    }

    private static void Kill(Process process)
    {
        try
        {
            if (!process.HasExited) process.Kill(entireProcessTree: true);
            process.WaitForExit(5000);
        }
        catch (InvalidOperationException)
        {
            // Already gone.
        }
        process.Dispose();
    }

    /// <summary>Stops the process, or with <see cref="ReuseProcesses"/> keeps a healthy one for the next bridge.</summary>
    public void Dispose()
    {
        if (ReuseProcesses && _process is { HasExited: false } process)
        {
            var idle = Idle.GetOrAdd(IdleKey, _ => []);
            if (idle.Count < MaxIdleProcesses)
            {
                idle.Add((process, _stderr, QSharpVersion));
                _process = null;
                return;
            }
        }
        Stop();
    }

    /// <summary>The process ended under a request: the one case that is retried after a restart.</summary>
    private sealed class BridgeDiedException(string message) : Exception(message);
}
