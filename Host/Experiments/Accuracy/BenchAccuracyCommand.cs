using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench accuracy`: options → <see cref="AccuracySettings"/> → <see cref="AccuracyExperiment"/> (docs/accuracy.md).</summary>
public sealed class BenchAccuracyCommand : Command
{
    public const string CommandText = "qrt bench accuracy";

    private readonly Option<int[]> _sizes = CommonOptions.SquareSizes("Square image sizes (space-separated).", [4, 8, 16, 32, 64, 128]);

    private readonly Option<int> _seeds = CommonOptions.SeedCount("Random scenes per kind and size (seeds 1..n).", 10, max: 1000);

    private readonly Option<int> _deepSize = CommonOptions.SquareSize("Largest size rendered for the 4,000-rectangle scenes (their rays each test 4,000 primitives classically).", 64, "--deep-size");

    private readonly Option<int[]> _growth = CommonOptions.List("--growth-sizes", "Scattered random scene sizes N of the table of where the budget spends its queries (space-separated).",
        AccuracySettings.DefaultGrowth, "N", 1, 8192);

    private readonly Option<int> _growthSeeds = CommonOptions.SeedCount("Scattered scenes per N (seeds 1..n) of the default's spread in the table of where the budget spends its queries.",
        AccuracySettings.DefaultGrowthSeeds, max: 1000, name: "--growth-seeds");

    private readonly Option<bool> _growthOnly = new("--growth-only") { Description = "Measure only the table of where the budget spends its queries (--growth)." };

    private readonly BenchReportOptions _report = new(CommandText, "docs/accuracy.md");

    public BenchAccuracyCommand() : base("accuracy", "Wrong pixels and Int/Ray of the default pipeline on random scenes by size, beside --lattice 0 and the paper's plain pipeline (analytic engine).")
    {
        this.AddOptions(_sizes, _seeds, _deepSize, _growth, _growthSeeds, _growthOnly);
        _report.AddTo(this, scenes: false, seed: false, workers: false);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var settings = new AccuracySettings(parse.GetValue(_sizes)!, parse.GetValue(_seeds), parse.GetValue(_deepSize), DefaultScene.Load(null))
        {
            Growth = parse.GetValue(_growth)!,
            GrowthOnly = parse.GetValue(_growthOnly),
            GrowthSeeds = parse.GetValue(_growthSeeds),
        };
        var report = AccuracyExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(null, null)));
        return ExitCodes.Success;
    }
}
