using System.CommandLine;
using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Search;
using Spectre.Console;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `search`: runs many QSearch instances over one marked set in lock step on the chosen engine and
/// reports what they found and what they cost.
/// </summary>
public sealed class SearchCommand : Command
{
    private readonly Option<int> _count = new("--count", "-n")
    {
        Description = "N, the number of indices searched (1 to 4096).",
        DefaultValueFactory = _ => 64,
    };

    private readonly Option<int[]> _marked = new("--marked", "-m")
    {
        Description = "Marked indices in 0..N-1, space-separated (e.g. -m 3 17). Default: one index drawn from the seed. Use -m with no values for none.",
        AllowMultipleArgumentsPerToken = true,
        Arity = ArgumentArity.ZeroOrMore,
    };

    private readonly Option<int> _searches = new("--searches", "-s")
    {
        Description = "Independent searches run side by side, one engine call per round for all of them.",
        DefaultValueFactory = _ => 100,
    };

    private readonly QSearchOptionSet _qsearch = new();

    private readonly EngineOptions _engine = new(EngineKind.FullState, EngineKind.FullState, EngineKind.Analytic);

    private readonly JsonOption _json = new();

    public SearchCommand() : base("search", "Grover search with QSearch (adaptive exponential search) over N indices with a given marked set.")
    {
        Options.Add(_count);
        Options.Add(_marked);
        Options.Add(_searches);
        _qsearch.AddTo(this);
        _engine.AddTo(this);
        _json.AddTo(this);
        _count.Between(1, 4096);
        _searches.AtLeast(1);
        Validators.Add(r =>
        {
            var n = r.GetValue(_count);
            var marked = r.GetValue(_marked) ?? [];
            var outside = marked.Where(m => m < 0 || m >= n).ToArray();
            if (outside.Length > 0)
                r.AddError($"--marked: index {outside[0]} is outside 0..{n - 1}");
            else if (marked.Distinct().Count() != marked.Length)
                r.AddError("--marked: an index is listed twice");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        _json.EnsureWritable(parse, []);
        using var bridges = _engine.StartBridges(parse);
        var settings = new SearchRunSettings(parse.GetValue(_count), parse.GetResult(_marked) is null ? null : parse.GetValue(_marked) ?? [],
            parse.GetValue(_searches), _qsearch.Get(parse), parse.GetValue(_engine.Engine), parse.GetValue(_engine.Seed),
            parse.GetValue(_engine.Workers), parse.GetValue(_engine.MaxQubits), _engine.GetNoise(parse), bridges);
        var (marked, registers) = (settings.MarkedSet, settings.Registers);

        AnsiConsole.WriteLine($"N = {settings.Count}, marked = [{string.Join(", ", marked.Indices.ToArray())}] (t = {marked.MarkedCount}), M_l = {{{string.Join(", ", settings.Schedule.Bounds)}}}");
        AnsiConsole.WriteLine($"registers per search: {registers.IndexQubits} index qubits + {registers.AuxiliaryQubits} auxiliaries for the multi-controlled phase");
        var noise = EngineFactory.NoiseDescription(settings.Engine, settings.NoiseModel);
        AnsiConsole.WriteLine($"noise model: {noise}");

        var run = AnsiConsole.Profile.Capabilities.Interactive
            ? AnsiConsole.Progress().AutoClear(true).Start(progress =>
            {
                var task = progress.AddTask($"{EngineFactory.Name(settings.Engine)}: searching", maxValue: settings.Searches);
                return SearchRun.Run(settings, (_, active) => task.Value = settings.Searches - active);
            })
            : SearchRun.Run(settings);

        var figures = run.Figures;
        var table = new Table().AddColumns("measure", "value");
        table.AddRow("searches", N(figures.Searches));
        table.AddRow("found / not found", $"{N(figures.Found)} / {N(figures.NotFound)}");
        table.AddRow("#Eval per search, conservative", Per(figures.QueriesConservativePerSearch));
        table.AddRow("#Eval per search, paper", Per(figures.QueriesPaperPerSearch));
        table.AddRow("#C_Int per search", Per(figures.ClassicalTestsPerSearch));
        table.AddRow("Grover runs per search", Per(figures.GroverRunsPerSearch));
        table.AddRow("engine calls (rounds)", N(figures.Rounds));
        table.AddRow("noise model", noise);
        table.AddRow("wall time", $"{figures.WallTime.TotalSeconds.ToString("0.000", CultureInfo.InvariantCulture)} s");
        table.AddRow("ran on", Markup.Escape(run.RanOn.Description));
        AnsiConsole.Write(table);
        AnsiConsole.MarkupLine("[grey]#Eval conservative counts r + 1 per Grover run with r ≥ 1 iterations, paper counts r; the initial sample costs none (docs/conventions.md).[/]");
        _json.Write(parse, figures, _engine, run.RanOn);
        return 0;
    }

    private static string Per(double value) => value.ToString("0.00", CultureInfo.InvariantCulture);

    private static string N(int value) => value.ToString(CultureInfo.InvariantCulture);
}
