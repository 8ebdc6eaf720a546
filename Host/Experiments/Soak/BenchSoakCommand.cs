using System.CommandLine;
using QuantumRayTracing.Views;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Scenes;
using Spectre.Console;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench soak`: every scene in a directory on every engine that can hold it, with two seeds, each render
/// checked (<see cref="Soak"/>); a table per scene and engine, optionally written as Markdown
/// (docs/soak.md), and exit code <see cref="ExitCodes.ChecksFailed"/> when any check failed.
/// </summary>
public sealed class BenchSoakCommand : Command
{
    public const string CommandText = "qrt bench soak";

    // Not BenchReportOptions' scene directory, where experiments look scenes up by name: every scene in it is soaked.
    private readonly Option<DirectoryInfo?> _scenesToSoak = new("--scenes")
    {
        Description = "Directory of scene files (every *.json in it). Default: Scenes/ of the repository holding the current directory.",
    };

    private readonly Option<EngineKind[]> _engines = CommonOptions.Engines("Engines to soak (space- or comma-separated). Default: all five with randomness or a simulator, not bvh.",
        SoakSettings.AllEngines, [.. SoakSettings.AllEngines, EngineKind.Bvh]);

    private readonly Option<ulong[]> _seeds = new("--seeds")
    {
        Description = "Seeds each scene and engine renders with (space-separated); the checks between seeds need two or more.",
        DefaultValueFactory = _ => SoakSettings.DefaultSeeds,
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<bool> _short = new("--short")
    {
        Description = "The CI form: 4x4 images (gate 2x2), 2 TracePass and 1 DirectPass rounds, 2 area samples, fullstate and gate on the smallest scene only.",
    };

    // Sizes and samples left out take the full or the short form's.
    private readonly Option<int> _size = CommonOptions.SquareSize("Square image size for every engine but gate (short form: 4).", SoakSettings.DefaultSize);

    private readonly Option<int> _gateSize = new Option<int>("--gate-size")
    {
        Description = "Square image size for the gate engine, which simulates its whole oracle (short form: 2).",
        DefaultValueFactory = _ => SoakSettings.DefaultGateSize,
    }.Between(1, 64);

    private readonly Option<int> _areaSamples = CommonOptions.AreaSamples("Shadow rays per point and area light, as `render` (short form: 2).");

    private readonly Option<int> _vpl = CommonOptions.Vpl("VPLs per surface point (0: no indirect light, as `render`).");

    private readonly Option<double> _gateBudget = new("--gate-budget")
    {
        Description = "Seconds: skip a gate render forecast to take longer (rays x N^2.5 x 8 µs).",
        DefaultValueFactory = _ => SoakSettings.DefaultGateBudget.TotalSeconds,
    };

    private readonly Option<int?> _maxQubits = CommonOptions.MaxQubits($"Gate engine: a search needing more qubits at peak is refused before simulating; the soak reports the scene as skipped. Default: {GateEngine.DefaultMaxQubits}.");

    private readonly BenchReportOptions _report = new(CommandText, "docs/soak.md");

    public BenchSoakCommand() : base("soak", "Render every scene on every engine with two seeds; check each render (no exception, finite pixels, error against classical, same seed same bytes, another seed another render) and report failures.")
    {
        this.AddOptions(_scenesToSoak, _engines, _seeds, _short, _size, _gateSize, _areaSamples, _vpl, _gateBudget, _maxQubits);
        _report.AddTo(this, scenes: false, seed: false, cluster: true);
        _seeds.Validators.Add(r =>
        {
            if (!r.TryGetValue<ulong[]>(out var given)) return;
            var seeds = given ?? [];
            if (seeds.Length == 0) r.AddError("--seeds: give at least one seed");
            else if (seeds.Distinct().Count() != seeds.Length) r.AddError("--seeds: the seeds must differ");
        });
        _gateBudget.Validators.Add(r =>
        {
            if (r.TryGetValue<double>(out var seconds) && !(seconds >= 0)) r.AddError($"--gate-budget must be 0 or more seconds, got {seconds}");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var directory = parse.GetValue(_scenesToSoak)?.FullName ?? RepositoryScenes.Find(Environment.CurrentDirectory)
            ?? throw new UserError("--scenes: no Scenes/ folder of this repository above the current directory; name the scene directory");
        if (!Directory.Exists(directory)) throw new UserError($"--scenes: {directory} does not exist");
        var files = Directory.GetFiles(directory, "*.json").Order(StringComparer.Ordinal).ToArray();
        if (files.Length == 0) throw new UserError($"--scenes: {directory} holds no *.json scene files");

        using var cluster = _report.StartBridges(parse);
        var workers = parse.GetValue(_report.Workers);
        var settings = parse.GetValue(_short) ? SoakSettings.Short(workers) : SoakSettings.Full(workers);
        settings = settings with
        {
            Engines = parse.GetValue(_engines)!,
            Seeds = parse.GetValue(_seeds)!,
            Size = CommonOptions.Given(parse, _size) ?? settings.Size,
            GateSize = CommonOptions.Given(parse, _gateSize) ?? settings.GateSize,
            AreaSamples = CommonOptions.Given(parse, _areaSamples) ?? settings.AreaSamples,
            Vpl = parse.GetValue(_vpl),
            GateBudget = TimeSpan.FromSeconds(parse.GetValue(_gateBudget)),
            MaxQubits = parse.GetValue(_maxQubits) ?? GateEngine.DefaultMaxQubits,
            Pool = cluster,
        };
        AnsiConsole.WriteLine($"soak: {files.Length} scene files in {directory}, engines {string.Join(", ", settings.Engines.Select(EngineFactory.Name))}, seeds {string.Join(" ", settings.Seeds)}, {settings.Size}x{settings.Size} (gate {settings.GateSize}x{settings.GateSize})");

        ConsoleProgress? current = null;
        var result = SoakExperiment.Run(files, settings,
            label =>
            {
                current?.Finish();
                return current = new ConsoleProgress(label);
            },
            row =>
            {
                current?.Finish();
                var engine = row.Engine is { } kind ? EngineFactory.Name(kind) : "(no engine)";
                Console.Error.WriteLine($"{row.Scene} on {engine}: {row.StatusText}");
            });

        SoakMatrixView.Print(result);
        // The console gets the matrix above, which fits 80 columns; the report's wide table goes to the file only.
        writer.Write(result.Report, ReportFooter.Lines(MachineDescription.Describe(result.Versions.QSharp, result.Versions.Node), cluster), print: false);
        return result.Failed ? ExitCodes.ChecksFailed : ExitCodes.Success;
    }
}
