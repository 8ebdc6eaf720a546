using System.CommandLine;
using System.CommandLine.Parsing;
using QuantumRayTracing.Views;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `search`: runs many QSearch instances over one marked set in lock step on the chosen engine and
/// reports what they found and what they cost.
/// </summary>
public sealed class SearchCommand : Command
{
    private const int DefaultCount = 64;

    private readonly Option<int> _count = new Option<int>("--count", "-n")
    {
        Description = "N, the number of indices searched (1 to 4096).",
        DefaultValueFactory = _ => DefaultCount,
    }.Between(1, 4096);

    private readonly Option<int[]> _marked = new("--marked", "-m")
    {
        Description = "Marked indices in 0..N-1, space-separated (e.g. -m 3 17). Default: one index drawn from the seed. Use -m with no values for none.",
        AllowMultipleArgumentsPerToken = true,
        Arity = ArgumentArity.ZeroOrMore,
    };

    private readonly Option<int> _searches = new Option<int>("--searches", "-s")
    {
        Description = "Independent searches run side by side, one engine call per round for all of them.",
        DefaultValueFactory = _ => 100,
    }.AtLeast(1);

    private readonly QSearchOptionSet _qsearch = new();

    private readonly EngineOptions _engine = new(EngineKind.FullState, EngineKind.FullState, EngineKind.Analytic);

    private readonly JsonOption _json = new();

    public SearchCommand() : base("search", "Grover search with QSearch (adaptive exponential search) over N indices with a given marked set.")
    {
        this.AddOptions(_count, _marked, _searches);
        _qsearch.AddTo(this);
        _engine.AddTo(this);
        _json.AddTo(this);
        this.AddRule(r =>
        {
            if (SearchRunSettings.MarkedProblem(r.ValueOr(_count, DefaultCount), r.GetValue(_marked) ?? []) is { } problem) r.AddError(problem);
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        _json.EnsureWritable(parse, []);
        using var bridges = _engine.StartBridges(parse);
        var settings = new SearchRunSettings(parse.GetValue(_count), parse.GetResult(_marked) is null ? null : parse.GetValue(_marked) ?? [],
            parse.GetValue(_searches), _engine.GetSetup(parse, _qsearch.Get(parse)).OnBridges(bridges), parse.GetValue(_engine.Seed));
        EngineFactory.CheckNoise(settings.Engine.Kind, settings.Engine.NoiseModel, settings.Engine.Device, settings.Count);
        SearchRunView.PrintPlan(settings);
        var run = SearchRunView.RunWithProgress(settings);
        SearchRunView.Print(settings, run);
        _json.Write(parse, run.Figures, _engine, run.RanOn, settings.RunNoise);
        return ExitCodes.Success;
    }
}
