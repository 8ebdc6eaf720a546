using System.CommandLine;
using System.Globalization;
using System.Text;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes.Generation;
using Spectre.Console;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `bench accuracy`: wrong pixels and Int/Ray of the default pipeline on random scenes it was not tuned
/// on, by image size and scene kind, beside `--lattice 0` and the paper's plain pipeline. Written as
/// Markdown (docs/accuracy.md).
/// </summary>
public sealed class BenchAccuracyCommand : Command
{
    public const string CommandLine = "qrt bench accuracy";

    private readonly Option<int[]> _sizes = new("--sizes")
    {
        Description = "Square image sizes (space-separated).",
        DefaultValueFactory = _ => [4, 8, 16, 32, 64, 128],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<int> _seeds = new("--seeds")
    {
        Description = "Random scenes per kind and size (seeds 1..n).",
        DefaultValueFactory = _ => 10,
    };

    private readonly Option<int> _deepSize = new("--deep-size")
    {
        Description = "Largest size rendered for the 4,000-rectangle scenes (their rays each test 4,000 primitives classically).",
        DefaultValueFactory = _ => 64,
    };

    private const int AlternativesUpTo = 64;
    private const int AlternativeSeeds = 5;

    private readonly BenchReportOptions _report = new(CommandLine, "docs/accuracy.md");

    public BenchAccuracyCommand() : base("accuracy", "Wrong pixels and Int/Ray of the default pipeline on random scenes by size, beside --lattice 0 and the paper's plain pipeline (analytic engine).")
    {
        Options.Add(_sizes);
        Options.Add(_seeds);
        Options.Add(_deepSize);
        _report.AddTo(this, scenes: false, seed: false);
        _seeds.Between(1, 1000);
        _deepSize.Between(1, 1024);
        _sizes.Validators.Add(r =>
        {
            if (r.GetValueOrDefault<int[]>() is { } sizes && sizes.Any(s => s is < 1 or > 1024)) r.AddError("--sizes: each size must be 1..1024");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var report = _report.Report(parse);
        var sizes = parse.GetValue(_sizes)!;
        var seeds = Enumerable.Range(1, parse.GetValue(_seeds)).Select(s => (ulong)s).ToArray();
        var deepSize = parse.GetValue(_deepSize);
        var configurations = AccuracyBenchmark.Standard;
        var cases = RandomScene.Kinds.SelectMany(k => sizes.Where(s => k != RandomSceneKind.Deep || s <= deepSize).Select(s => (Kind: k, Size: s))).ToArray();

        var cells = new List<AccuracyCell>();
        AnsiConsole.Progress().AutoClear(true).Start(progress =>
        {
            var task = progress.AddTask("accuracy", maxValue: cases.Length);
            foreach (var (kind, size) in cases)
            {
                cells.AddRange(AccuracyBenchmark.Measure(kind, size, seeds, configurations));
                task.Increment(1);
            }
        });

        var text = new StringBuilder();
        text.AppendLine("# Accuracy of the default pipeline at every image size");
        text.AppendLine();
        text.AppendLine($"Random scenes the pipeline was not tuned on (`RandomScene`, {seeds.Length} seeds per kind and size), analytic engine. *Wrong pixels*: pixels whose");
        text.AppendLine("8-bit RGB differs from the classical render of the same scene and size, summed over the seeds, and their share. *Expected*: the");
        text.AppendLine("wrong pixels the default's searches allow, summed over the seeds (`render` prints it per image; docs/rendering.md says how it is estimated).");
        text.AppendLine($"Int/Ray in the conservative count (r + 1 per Grover run), over all rays of all seeds. The budget: at most {AccuracyBudget.Target:P1} of pixels wrong, in expectation.");
        text.AppendLine("*Default*: `render` with no options (lattice levels from the image size); *--lattice 0*: the same without lattice-first tracing;");
        text.AppendLine("*paper, plain*: 4 TracePass rounds, 2 DirectPass rounds, no neighbours, no termination, the paper's M sets (round(c^l)).");
        text.AppendLine();
        text.Append("| scene kind | size | lattice levels |");
        foreach (var c in configurations) text.Append($" {c.Name}: wrong pixels | share | Int/Ray |");
        text.AppendLine(" default: expected wrong |");
        text.Append("|---|---|---|");
        foreach (var _ in configurations) text.Append("---|---|---|");
        text.AppendLine("---|");
        foreach (var group in cells.GroupBy(c => (c.Kind, c.Size)))
        {
            var row = group.ToArray();
            text.Append($"| {RandomSceneKindName(group.Key.Kind)} | {group.Key.Size}x{group.Key.Size} | {RenderDefaults.LatticeLevelsFor(group.Key.Size, group.Key.Size)} |");
            foreach (var cell in row) text.Append($" {cell.WrongPixels} of {cell.Pixels:N0} | {cell.WrongShare:P2} | {cell.IntPerRay:0.0} |");
            text.AppendLine($" {row[0].AllowedWrong:0.0} |");
        }
        text.AppendLine();
        text.AppendLine("## The Qornell box, 64 primitives (`render`'s built-in scene, seed 1)");
        text.AppendLine();
        text.AppendLine("| size | configuration | wrong pixels | Int/Ray (conservative) | default: expected wrong pixels |");
        text.AppendLine("|---|---|---|---|---|");
        var qornell = RenderCommand.LoadScene(null);
        foreach (var size in new[] { 8, 128 })
        {
            var reference = RenderMeasurement.Reference(qornell, new RenderOptions(size, size));
            foreach (var c in configurations)
            {
                var m = RenderMeasurement.Run(qornell, Engines.EngineKind.Analytic, c.Options(size, 1), c.QSearch, 1, 1, reference);
                var expected = c == configurations[0] ? $"{m.Result.Budget.ExpectedWrongPixels:0.0}" : "";
                text.AppendLine($"| {size}x{size} | {c.Name} | {m.Error.DifferentPixels} of {size * size:N0} | {m.Result.Total.PerRayConservative:0.00} | {expected} |");
            }
        }
        text.AppendLine();
        // The alternatives, on every kind but the 4,000-rectangle scenes, at the small sizes where they differ.
        var alternativeSizes = sizes.Where(s => s <= AlternativesUpTo).ToArray();
        var alternativeSeeds = seeds.Take(AlternativeSeeds).ToArray();
        text.AppendLine("## The ways to keep the budget, measured");
        text.AppendLine();
        text.AppendLine($"Every kind but the 4,000-rectangle scenes, {alternativeSeeds.Length} seeds per kind and size; wrong pixels summed, Int/Ray (conservative) over all rays.");
        text.AppendLine("*4 levels at every size, 1 miss, 4 rounds*: the pipeline before the budget, except that a ray is vouched for only by all its lattice");
        text.AppendLine("neighbours (before, whatever neighbours it had could vouch for it). The others undo one rule of the default: required misses (1, the");
        text.AppendLine("paper's stop rule), lattice levels (one fewer), or tighten the cheap confirmation. Where a row keeps the budget for less Int/Ray than the");
        text.AppendLine("default at every size, the default should be that row; where it costs more, the default's rule is the cheaper way to the budget.");
        text.AppendLine();
        text.Append("| configuration |");
        foreach (var size in alternativeSizes) text.Append($" {size}x{size}: wrong | Int/Ray |");
        text.AppendLine();
        text.Append("|---|");
        foreach (var _ in alternativeSizes) text.Append("---|---|");
        text.AppendLine();
        var alternatives = AccuracyBenchmark.Alternatives;
        var measured = alternativeSizes.ToDictionary(size => size, size => RandomScene.Kinds.Where(k => k != RandomSceneKind.Deep)
            .SelectMany(kind => AccuracyBenchmark.Measure(kind, size, alternativeSeeds, alternatives)).ToArray());
        foreach (var c in alternatives)
        {
            text.Append($"| {c.Name} |");
            foreach (var size in alternativeSizes)
            {
                var row = measured[size].Where(cell => cell.Configuration == c.Name).ToArray();
                var (wrong, pixels) = (row.Sum(r => r.WrongPixels), row.Sum(r => r.Pixels));
                var intPerRay = (double)row.Sum(r => r.IntersectionsConservative) / row.Sum(r => r.Rays);
                text.Append($" {wrong} of {pixels:N0} ({(double)wrong / pixels:P2}) | {intPerRay:0.0} |");
            }
            text.AppendLine();
        }
        text.AppendLine();
        var byConfiguration = cells.GroupBy(c => c.Configuration).Select(g => (g.Key, Wrong: g.Sum(c => c.WrongPixels), Pixels: g.Sum(c => c.Pixels))).ToArray();
        text.AppendLine("All kinds and sizes together: " + string.Join("; ", byConfiguration.Select(c => $"{c.Key} {c.Wrong} of {c.Pixels:N0} pixels wrong ({(double)c.Wrong / c.Pixels:P3})")) + ".");
        BenchReportOptions.Publish(report, text);
        return 0;
    }

    private static string RandomSceneKindName(RandomSceneKind kind) => kind switch
    {
        RandomSceneKind.Scattered => "scattered, N = 37",
        RandomSceneKind.Ties => "ties, N = 24",
        RandomSceneKind.SharedEdges => "shared edges",
        RandomSceneKind.Deep => "deep, N = 4,000",
        RandomSceneKind.Fractional => "fractional grid, N = 29",
        _ => kind.ToString(),
    };
}
