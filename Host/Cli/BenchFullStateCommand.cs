using System.CommandLine;
using System.Globalization;
using System.Text;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Bridge;
using static QuantumRayTracing.Benchmarks.FullStateBenchmark;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `bench fullstate`: whole renders on the fullstate engine, the current engine beside the baseline it
/// replaced, each render's time split into bridge calls and simulation, and the simulator-only floor.
/// </summary>
public sealed class BenchFullStateCommand : Command
{
    public const string CommandLine = "qrt bench fullstate";

    private readonly BenchReportOptions _report = new(CommandLine, "docs/performance-fullstate.md");

    private readonly Option<string[]> _sceneNames = new("--scene-names")
    {
        Description = "Scene files (names without .json in the scene directory), space-separated.",
        DefaultValueFactory = _ => ["qornell-64", "qornell-512"],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<int[]> _sizes = new("--sizes")
    {
        Description = "Square image sizes, space-separated.",
        DefaultValueFactory = _ => [32, 64, 128],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<long> _baselineLimit = new("--baseline-limit")
    {
        Description = "The baseline engine (the slow one) also renders a case only up to this many pixels × primitives; 0 for never. Default: qornell-64 up to 128², qornell-512 up to 64².",
        DefaultValueFactory = _ => 2L * 64 * 64 * 512,
    };

    public BenchFullStateCommand() : base("fullstate", "Whole renders on the fullstate engine against its baseline: ms per ray, bridge calls, time in calls against simulation, and the simulator-only floor.")
    {
        _report.AddTo(this);
        Options.Add(_sceneNames);
        Options.Add(_sizes);
        Options.Add(_baselineLimit);
        _sizes.Validators.Add(r =>
        {
            if ((r.GetValueOrDefault<int[]>() ?? []).Any(n => n is < 1 or > 1024)) r.AddError("--sizes: each size must be between 1 and 1024");
        });
        _baselineLimit.Validators.Add(r =>
        {
            if (r.GetValueOrDefault<long>() < 0) r.AddError("--baseline-limit must be at least 0");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var report = _report.Report(parse);
        var seed = parse.GetValue(_report.Seed);
        var workers = parse.GetValue(_report.Workers);
        var baselineLimit = parse.GetValue(_baselineLimit);
        var scenes = parse.GetValue(_sceneNames)!.Select(name => (Name: name, Scene: _report.Load(parse, name))).ToArray();
        string versions;
        using (var bridge = new QSharpBridge())
        {
            var v = bridge.Version();
            versions = MachineDescription.Describe(v["qsharp"]?.GetValue<string>(), v["node"]?.GetValue<string>());
        }
        var rows = new List<Row>();
        foreach (var (name, scene) in scenes)
            foreach (var size in parse.GetValue(_sizes)!)
            {
                // Back to back, so both see the same load on a shared machine.
                Variant[] variants = (long)size * size * new Intersection.SceneGeometry(scene).Count <= baselineLimit ? [Variant.Baseline, Variant.Current] : [Variant.Current];
                foreach (var variant in variants)
                {
                    Console.Error.WriteLine($"rendering {name} at {size}x{size} on the {(variant == Variant.Current ? "current" : "baseline")} fullstate engine");
                    rows.Add(FullStateBenchmark.Run(name, scene, size, variant, workers, seed));
                }
            }
        var text = Markdown(rows, workers, seed);
        BenchReportOptions.AppendFooter(text, versions);
        var body = text.ToString();
        Console.WriteLine(body);
        report.Write(body);
        return 0;
    }

    private static StringBuilder Markdown(List<Row> rows, int workers, ulong seed)
    {
        static string F(double v, string format) => v.ToString(format, CultureInfo.InvariantCulture);
        static string Engine(Variant v) => v == Variant.Current ? "current" : "baseline";
        var text = new StringBuilder();
        text.AppendLine("# Performance: whole renders on the fullstate engine");
        text.AppendLine();
        text.AppendLine($"`render --engine fullstate` with the default pipeline (seed {seed}, {workers} workers), timed from the first search to the image,");
        text.AppendLine("on the current engine and on the baseline it replaced, rendered back to back:");
        text.AppendLine();
        text.AppendLine("- **baseline**: QSearch in lock-step rounds, one bridge call per round and worker, and the oracle and the reflection's S₀ built");
        text.AppendLine("  from the standard library's `Controlled Z` on a flag qubit (`MeasureGroverBatchWithControlledZ`), as the engine was first built;");
        text.AppendLine("- **current**: each search's remaining Grover runs planned at once and run in one call (`MeasureGroverSchedules`, stopping at the");
        text.AppendLine("  first marked index), and the phase on the all-ones state as a Toffoli ladder into auxiliaries allocated once per search.");
        text.AppendLine();
        text.AppendLine("Both run the same algorithm: the same QSearch schedules and counts (Int/Ray differs only by the simulator's unseeded outcomes).");
        text.AppendLine("*Calls* are the bridge requests of the render; *in calls* is the time the host waited for them, summed over the workers. The");
        text.AppendLine("*call floor* is the fixed cost of one call (the QDK compiles the program and its standard library on every call), measured");
        text.AppendLine("before each render as the median of 9 calls of one Grover run over one index; *floor share* = calls × call floor / time in");
        text.AppendLine("calls. The rest of the time in calls is the simulation: divided by the Grover runs it is the cost per run, and divided by");
        text.AppendLine("the workers and the rays it is the *simulator-only floor* per ray, the time a render would take if calls cost nothing and");
        text.AppendLine("the host's own work were free.");
        text.AppendLine();
        text.AppendLine("*Load* is the machine's 1-minute load average after the render: on a machine shared with other work the absolute times");
        text.AppendLine("grow with it (the call floor, the same call every time, shows by how much), so compare the two engines by the ratios of");
        text.AppendLine("renders run back to back, below.");
        text.AppendLine();
        text.AppendLine("| scene | size | engine | rays | wall | ms/ray | calls | in calls | call floor | floor share | Grover runs | simulation ms/run | simulator-only floor ms/ray | load |");
        text.AppendLine("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
        foreach (var r in rows)
            text.AppendLine($"| {r.Scene} | {r.Size}² | {Engine(r.Variant)} | {r.Rays:N0} | {F(r.Wall.TotalSeconds, "0.0")} s | {F(r.MillisecondsPerRay, "0.00")} | {r.Calls:N0} | {F(r.CallTime.TotalSeconds, "0.0")} s | {F(r.CallFloorMs, "0")} ms | {F(100 * r.FloorShare, "0")} % | {r.GroverRuns:N0} | {F(r.SimulationMsPerRun, "0.000")} | {F(r.FloorMsPerRay, "0.00")} | {(double.IsNaN(r.LoadAverage) ? "?" : F(r.LoadAverage, "0.0"))} |");
        var pairs = rows.Where(r => r.Variant == Variant.Current)
            .Select(c => (Current: c, Baseline: rows.FirstOrDefault(b => b.Variant == Variant.Baseline && b.Scene == c.Scene && b.Size == c.Size)))
            .Where(p => p.Baseline is not null).ToArray();
        if (pairs.Length > 0)
        {
            text.AppendLine();
            text.AppendLine("Baseline against current, measured back to back (ratios hold better than absolute times on a shared machine):");
            text.AppendLine();
            text.AppendLine("| scene | size | wall: baseline / current | calls: baseline / current | simulation ms/run: baseline / current |");
            text.AppendLine("|---|---|---|---|---|");
            foreach (var (c, b) in pairs)
                text.AppendLine($"| {c.Scene} | {c.Size}² | {F(b!.Wall / c.Wall, "0.0")}x | {F((double)b.Calls / c.Calls, "0.0")}x | {F(b.SimulationMsPerRun / c.SimulationMsPerRun, "0.0")}x |");
        }
        return text;
    }
}
