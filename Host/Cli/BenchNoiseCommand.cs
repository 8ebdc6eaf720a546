using System.CommandLine;
using System.Globalization;
using System.Text;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `bench noise`: the depolarizing approximation against the noisy simulator, the paper's device experiment
/// (fig. 15) under Pauli noise, and rendering under noise; writes docs/noise.md and its plots.
/// </summary>
public sealed class BenchNoiseCommand : Command
{
    private const string CommandText = "qrt bench noise";

    private readonly Option<int> _shots = new("--shots")
    {
        Description = "Runs per case of the model check.",
        DefaultValueFactory = _ => 2000,
    };

    private readonly Option<int> _deviceShots = new("--device-shots")
    {
        Description = "Measurements per error rate of the device experiment (the paper's fig. 15 took 1024).",
        DefaultValueFactory = _ => 1024,
    };

    private readonly Option<int> _size = new("--size")
    {
        Description = "Pixels per side of the noisy renders on the analytic engine.",
        DefaultValueFactory = _ => 128,
    };

    private readonly Option<int> _confirmSize = new("--confirm-size")
    {
        Description = "Pixels per side of the renders on the noisy fullstate engine that confirm the analytic model (0 skips them).",
        DefaultValueFactory = _ => 32,
    };

    private readonly Option<double[]> _confirmRates = new("--confirm-rates")
    {
        Description = "Per-gate error rates of the fullstate confirmation renders (space-separated).",
        DefaultValueFactory = _ => [1e-4, 1e-3, 1e-2],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<DirectoryInfo> _scenes = new("--scenes")
    {
        Description = "Directory holding qornell-64.json and depth-complexity-64.json.",
        DefaultValueFactory = _ => new DirectoryInfo("Scenes"),
    };

    private readonly Option<string[]> _parts = new("--parts")
    {
        Description = "Which parts to run and report: model (the approximation against the simulator), device (fig. 15), render (rendering under noise).",
        DefaultValueFactory = _ => ["model", "device", "render"],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<int> _workers = new("--workers")
    {
        Description = "Node bridge processes. Default: the core count.",
        DefaultValueFactory = _ => BridgePool.DefaultWorkers,
    };

    private readonly Option<FileInfo?> _output = new("--output", "-o")
    {
        Description = "Write the Markdown report here (e.g. docs/noise.md), with its PNG plots beside it as <report>-<name>.png. It replaces only files this command wrote before. Default: the report is printed only.",
    };

    public BenchNoiseCommand() : base("noise", "Hardware noise: the analytic noise model against the noisy simulator, the paper's device experiment (fig. 15), rendering under noise; -o docs/noise.md.")
    {
        Options.Add(_shots);
        Options.Add(_deviceShots);
        Options.Add(_size);
        Options.Add(_confirmSize);
        Options.Add(_confirmRates);
        Options.Add(_scenes);
        Options.Add(_parts);
        Options.Add(_workers);
        Options.Add(_output);
        _size.Between(1, 1024);
        _confirmSize.Between(0, 128);
        _confirmRates.Validators.Add(r =>
        {
            if ((r.GetValueOrDefault<double[]>() ?? []).Any(p => !(p > 0 && p <= 1))) r.AddError("--confirm-rates: each rate must lie in (0, 1]");
        });
        _parts.Validators.Add(r =>
        {
            foreach (var part in r.GetValueOrDefault<string[]>() ?? [])
                if (part is not ("model" or "device" or "render")) r.AddError($"--parts: '{part}' is not one of model, device, render");
        });
        _shots.Between(100, 1_000_000);
        _deviceShots.Between(16, 1_000_000);
        _workers.AtLeast(1);
        SetAction(Execute);
    }

    /// <summary>Per-gate error rates of the device experiment.</summary>
    public static readonly double[] DeviceRates = [0, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1];

    private int Execute(ParseResult parse)
    {
        var output = parse.GetValue(_output);
        var report = new GeneratedReport(output?.FullName, GeneratedReport.MarkdownMarker(CommandText));
        report.EnsureWritable();
        string PlotPath(string name) => Path.Combine(output?.DirectoryName ?? ".", $"{Path.GetFileNameWithoutExtension(output?.Name ?? "noise")}-{name}.png");
        var parts = parse.GetValue(_parts)!.ToHashSet();
        string[] renderScenes = ["qornell-64", "depth-complexity-64"];
        var plotNames = new List<string>();
        if (parts.Contains("model")) plotNames.Add("model-check");
        if (parts.Contains("device")) plotNames.AddRange(["device-histograms", "device-distance"]);
        if (parts.Contains("render")) plotNames.AddRange(renderScenes.SelectMany(n => new[] { $"render-{n}", $"int-per-ray-{n}" }));
        if (output is not null) ImageFiles.EnsureWritable(plotNames.Select(PlotPath).ToArray(), []);
        var scenes = parts.Contains("render")
            ? renderScenes.Select(n => (Name: n, Scene: Scenes.SceneLoader.Load(Path.Combine(parse.GetValue(_scenes)!.FullName, n + ".json")))).ToArray()
            : [];
        var size = parse.GetValue(_size);
        var confirmSize = parse.GetValue(_confirmSize);
        var confirmRates = parse.GetValue(_confirmRates)!;

        var shots = parse.GetValue(_shots);
        var deviceShots = parse.GetValue(_deviceShots);
        string machine;
        IReadOnlyList<NoiseCheckRow> check = [];
        IReadOnlyList<NoiseBenchmark.DeviceRun> device = [];
        CircuitCounts? deviceSearch = null, deviceOracle = null;
        var sweeps = new List<NoisyRenderBenchmark.Sweep>();
        var confirmations = new List<(string, double, RenderMeasurement, RenderMeasurement)>();
        var clock = System.Diagnostics.Stopwatch.StartNew();
        using (var pool = new BridgePool(parse.GetValue(_workers)))
        {
            var versions = pool.Bridges[0].Version();
            machine = MachineDescription.Describe(versions["qsharp"]?.GetValue<string>(), versions["node"]?.GetValue<string>()) + " (shared with other work while measured)";
            if (parts.Contains("model"))
            {
                Console.Error.WriteLine($"model check: {NoiseBenchmark.CheckRequests().Count} runs x {NoiseBenchmark.CheckRates.Length} error rates x {shots} shots");
                check = NoiseCheck.Measure(pool, NoiseBenchmark.CheckRequests(), NoiseBenchmark.CheckRates.Select(p => NoiseModel.Depolarizing(p)).ToArray(), shots);
            }
            if (parts.Contains("device"))
            {
                Console.Error.WriteLine($"device experiment: {DeviceRates.Length} error rates x {deviceShots} shots ({clock.Elapsed.TotalSeconds:0} s so far)");
                device = NoiseBenchmark.DeviceExperiment(pool, DeviceRates, deviceShots);
            }
            var ray = DeviceExperimentScene.Ray();
            var argument = GateEngine.OracleArgument(ray);
            CircuitCounts Trace(string expression)
            {
                CircuitCounts? counts = null;
                pool.ForEach([expression], (e, bridge) => counts = CircuitCounts.Parse(bridge.Circuit(e)));
                return counts!;
            }
            if (parts.Contains("device"))
            {
                deviceSearch = Trace($"QuantumRayTracing.Intersection.MeasureGateGroverSearch({argument}, 1)");
                deviceOracle = Trace($"QuantumRayTracing.Intersection.ApplyIntersectionOracleOnNewRegisters({argument})");
            }
        }
        // The renders: analytic at full size (no bridge), then the fullstate confirmations on their own pool.
        foreach (var (name, scene) in scenes)
            sweeps.Add(NoisyRenderBenchmark.Run(name, scene, size, NoisyRenderBenchmark.Rates, 16, message => Console.Error.WriteLine($"{message} ({clock.Elapsed.TotalSeconds:0} s so far)")));
        if (confirmSize > 0 && scenes.Length > 0)
        {
            var (name, scene) = scenes[0];
            var classical = RenderMeasurement.Reference(scene, NoisyRenderBenchmark.Defaults(confirmSize));
            foreach (var p in confirmRates)
            {
                Console.Error.WriteLine($"{name} at {confirmSize}x{confirmSize}: fullstate and analytic, p = {p} ({clock.Elapsed.TotalSeconds:0} s so far)");
                var analytic = RenderMeasurement.Run(scene, EngineKind.Analytic, NoisyRenderBenchmark.Defaults(confirmSize), new Search.QSearchOptions(), 1, 1, classical, NoiseModel.Depolarizing(p));
                confirmations.Add((name, p, analytic, NoisyRenderBenchmark.FullState(scene, confirmSize, p, parse.GetValue(_workers), classical)));
            }
        }
        var elapsed = clock.Elapsed;

        var arguments = string.Join(' ', Environment.GetCommandLineArgs().Skip(1));
        var command = $"dotnet run --project Host -c Release -- {arguments}";
        var text = new StringBuilder();
        var plots = new List<(RgbImage Image, string Path)>();
        string Plot(string name, RgbImage image, string caption)
        {
            var path = PlotPath(name);
            plots.Add((image, path));
            return $"![{caption}]({Path.GetFileName(path)})";
        }

        text.AppendLine("# Hardware noise");
        text.AppendLine();
        text.AppendLine("What Pauli noise does to the quantum searches: the analytic noise model proven against the noisy simulator, the ray tracing");
        text.AppendLine("paper's device experiment (sec. 8, fig. 15) reproduced on the simulator, and what noise costs a render.");
        text.AppendLine();
        text.AppendLine($"Regenerate: `{command}` ({elapsed.TotalMinutes:0.0} min). Machine: {machine}.");
        text.AppendLine();
        if (parts.Contains("model")) NoiseReport.Model(text, check, shots, (name, image, caption) => Plot(name, image, caption), machine);
        if (parts.Contains("device")) NoiseReport.Device(text, device, deviceShots, deviceSearch!, deviceOracle!, (name, image, caption) => Plot(name, image, caption), machine);
        if (parts.Contains("render")) NoiseReport.Render(text, sweeps, size, confirmations, confirmSize, (name, image, caption) => Plot(name, image, caption), machine);

        var body = text.ToString();
        Console.WriteLine(body);
        report.Write(body);
        if (output is not null) ImageFiles.Write(plots);
        return 0;
    }
}
