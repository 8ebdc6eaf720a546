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
        Options.Add(_workers);
        Options.Add(_output);
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
        string[] plotNames = ["model-check", "device-histograms", "device-distance"];
        if (output is not null) ImageFiles.EnsureWritable(plotNames.Select(PlotPath).ToArray(), []);

        var shots = parse.GetValue(_shots);
        var deviceShots = parse.GetValue(_deviceShots);
        string machine;
        IReadOnlyList<NoiseCheckRow> check;
        IReadOnlyList<NoiseBenchmark.DeviceRun> device;
        CircuitCounts deviceSearch, deviceOracle;
        var clock = System.Diagnostics.Stopwatch.StartNew();
        using (var pool = new BridgePool(parse.GetValue(_workers)))
        {
            var versions = pool.Bridges[0].Version();
            machine = MachineDescription.Describe(versions["qsharp"]?.GetValue<string>(), versions["node"]?.GetValue<string>()) + " (shared with other work while measured)";
            Console.Error.WriteLine($"model check: {NoiseBenchmark.CheckRequests().Count} runs x {NoiseBenchmark.CheckRates.Length} error rates x {shots} shots");
            check = NoiseCheck.Measure(pool, NoiseBenchmark.CheckRequests(), NoiseBenchmark.CheckRates.Select(p => NoiseModel.Depolarizing(p)).ToArray(), shots);
            Console.Error.WriteLine($"device experiment: {DeviceRates.Length} error rates x {deviceShots} shots ({clock.Elapsed.TotalSeconds:0} s so far)");
            device = NoiseBenchmark.DeviceExperiment(pool, DeviceRates, deviceShots);
            var ray = DeviceExperimentScene.Ray();
            var argument = GateEngine.OracleArgument(ray);
            CircuitCounts Trace(string expression)
            {
                CircuitCounts? counts = null;
                pool.ForEach([expression], (e, bridge) => counts = CircuitCounts.Parse(bridge.Circuit(e)));
                return counts!;
            }
            deviceSearch = Trace($"QuantumRayTracing.Intersection.MeasureGateGroverSearch({argument}, 1)");
            deviceOracle = Trace($"QuantumRayTracing.Intersection.ApplyIntersectionOracleOnNewRegisters({argument})");
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
        NoiseReport.Model(text, check, shots, (name, image, caption) => Plot(name, image, caption), machine);
        NoiseReport.Device(text, device, deviceShots, deviceSearch, deviceOracle, (name, image, caption) => Plot(name, image, caption), machine);

        var body = text.ToString();
        Console.WriteLine(body);
        report.Write(body);
        if (output is not null) ImageFiles.Write(plots);
        return 0;
    }
}
