using System.CommandLine;
using System.CommandLine.Parsing;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using Spectre.Console;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `bench soak`: every scene in a directory on every engine that can hold it, with two seeds, each render
/// checked (<see cref="Soak"/>); a table per scene and engine, optionally written as Markdown
/// (docs/soak.md), and exit code <see cref="ChecksFailed"/> when any check failed.
/// </summary>
public sealed class BenchSoakCommand : Command
{
    public const string CommandLine = "qrt bench soak";

    /// <summary>The exit code when a render failed a check: after the codes <see cref="Cli.CommandLine"/> gives every command.</summary>
    public const int ChecksFailed = 5;

    private readonly Option<DirectoryInfo?> _scenes = new("--scenes")
    {
        Description = "Directory of scene files (every *.json in it). Default: Scenes/ of the repository holding the current directory.",
    };

    private readonly Option<EngineKind[]> _engines = new("--engines")
    {
        Description = "Engines to soak (space- or comma-separated). Default: all five.",
        DefaultValueFactory = _ => SoakSettings.AllEngines,
        AllowMultipleArgumentsPerToken = true,
        HelpName = "classical|randomized|analytic|fullstate|gate",
    };

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

    private readonly Option<int?> _size = new("--size")
    {
        Description = $"Square image size for every engine but gate. Default: {SoakSettings.DefaultSize} (short form: 4).",
    };

    private readonly Option<int?> _gateSize = new("--gate-size")
    {
        Description = $"Square image size for the gate engine, which simulates its whole oracle. Default: {SoakSettings.DefaultGateSize} (short form: 2).",
    };

    private readonly Option<int?> _areaSamples = new("--area-samples")
    {
        Description = $"Shadow rays per point and area light. Default: {RenderDefaults.AreaSamples}, as `render` (short form: 2).",
    };

    private readonly Option<int> _vpl = new("--vpl")
    {
        Description = "VPLs per surface point (0: no indirect light, as `render`).",
        DefaultValueFactory = _ => RenderDefaults.Vpl,
    };

    private readonly Option<double> _gateBudget = new("--gate-budget")
    {
        Description = "Seconds: skip a gate render forecast to take longer (rays x N^2.5 x 8 µs).",
        DefaultValueFactory = _ => SoakSettings.DefaultGateBudget.TotalSeconds,
    };

    private readonly Option<int> _maxQubits = new("--max-qubits")
    {
        Description = "Gate engine: a search needing more qubits at peak is refused before simulating; the soak reports the scene as skipped.",
        DefaultValueFactory = _ => GateEngine.DefaultMaxQubits,
    };

    private readonly BenchReportOptions _report = new(CommandLine, "docs/soak.md");

    public BenchSoakCommand() : base("soak", "Render every scene on every engine with two seeds; check each render (no exception, finite pixels, error against classical, same seed same bytes, another seed another render) and report failures.")
    {
        Options.Add(_scenes);
        Options.Add(_engines);
        Options.Add(_seeds);
        Options.Add(_short);
        Options.Add(_size);
        Options.Add(_gateSize);
        Options.Add(_areaSamples);
        Options.Add(_vpl);
        Options.Add(_gateBudget);
        Options.Add(_maxQubits);
        _report.AddTo(this, scenes: false, seed: false, cluster: true);
        _engines.CustomParser = ParseEngines;
        _seeds.Validators.Add(r =>
        {
            var seeds = r.GetValueOrDefault<ulong[]>() ?? [];
            if (seeds.Length == 0) r.AddError("--seeds: give at least one seed");
            else if (seeds.Distinct().Count() != seeds.Length) r.AddError("--seeds: the seeds must differ");
        });
        _size.Between(1, 1024);
        _gateSize.Between(1, 64);
        _areaSamples.Between(1, CommonOptions.MaxSamples);
        _vpl.Between(0, CommonOptions.MaxSamples);
        _maxQubits.Between(1, 100_000);
        _gateBudget.Validators.Add(r =>
        {
            if (r.TryGetValue<double>(out var seconds) && !(seconds >= 0)) r.AddError($"--gate-budget must be 0 or more seconds, got {seconds}");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var directory = parse.GetValue(_scenes)?.FullName ?? RepositoryScenes(Environment.CurrentDirectory)
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
            Size = parse.GetValue(_size) ?? settings.Size,
            GateSize = parse.GetValue(_gateSize) ?? settings.GateSize,
            AreaSamples = parse.GetValue(_areaSamples) ?? settings.AreaSamples,
            Vpl = parse.GetValue(_vpl),
            GateBudget = TimeSpan.FromSeconds(parse.GetValue(_gateBudget)),
            MaxQubits = parse.GetValue(_maxQubits),
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

        PrintMatrix(result);
        // The console gets the matrix above, which fits 80 columns; the report's wide table goes to the file only.
        writer.Write(result.Report, BenchReportOptions.Footer(MachineDescription.Describe(result.Versions.QSharp, result.Versions.Node), cluster), print: false);
        return result.Failed ? ChecksFailed : 0;
    }

    // Scenes by engines, so the table fits 80 columns; the reasons follow it.
    private static void PrintMatrix(SoakResult result)
    {
        var rows = result.Rows;
        var engineKinds = rows.Where(r => r.Engine is not null).Select(r => r.Engine!.Value).Distinct().ToArray();
        var table = new Table().Title("soak: scenes by engines");
        table.AddColumn("scene");
        foreach (var kind in engineKinds) table.AddColumn(EngineFactory.Name(kind));
        foreach (var scene in rows.GroupBy(r => r.Scene))
            table.AddRow([Markup.Escape($"{scene.Key}\nN = {scene.First().Primitives}"),
                .. engineKinds.Select(k => scene.FirstOrDefault(r => r.Engine == k) is { } row ? Markup.Escape(SoakReport.MatrixCell(row)) : "")]);
        AnsiConsole.Write(table);
        foreach (var row in rows.Where(r => r.Status != SoakStatus.Ok))
            AnsiConsole.WriteLine($"{row.Scene}{(row.Engine is { } e ? " on " + EngineFactory.Name(e) : "")}: {row.StatusText}");
        AnsiConsole.WriteLine($"{SoakReport.Summary(rows)}; {result.Total.TotalSeconds:0.0} s");
    }

    /// <summary>Scenes/ of the repository (the directory holding QuantumRayTracing.sln) at or above <paramref name="start"/>, or null.</summary>
    public static string? RepositoryScenes(string start)
    {
        for (var directory = new DirectoryInfo(start); directory is not null; directory = directory.Parent)
        {
            var scenes = Path.Combine(directory.FullName, "Scenes");
            if (File.Exists(Path.Combine(directory.FullName, "QuantumRayTracing.sln")) && Directory.Exists(scenes)) return scenes;
        }
        return null;
    }

    // Engine names, space- or comma-separated, each at most once; listed in the report's order.
    private static EngineKind[] ParseEngines(ArgumentResult result)
    {
        var kinds = new List<EngineKind>();
        foreach (var name in result.Tokens.SelectMany(t => t.Value.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries)))
        {
            var match = Enum.GetNames<EngineKind>().FirstOrDefault(n => string.Equals(n, name, StringComparison.OrdinalIgnoreCase));
            if (match is null)
            {
                result.AddError($"--engines: '{name}' is not one of {string.Join(", ", SoakSettings.AllEngines.Select(EngineFactory.Name))}");
                return [];
            }
            var kind = Enum.Parse<EngineKind>(match);
            if (!kinds.Contains(kind)) kinds.Add(kind);
        }
        if (kinds.Count == 0) result.AddError("--engines: name at least one engine");
        return kinds.OrderBy(k => Array.IndexOf(SoakSettings.AllEngines, k)).ToArray();
    }
}
