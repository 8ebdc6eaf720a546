using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench bvh-comparison`: options → <see cref="BvhComparisonSettings"/> → <see cref="BvhComparisonExperiment"/> (docs/bvh-comparison.md).</summary>
public sealed class BenchBvhComparisonCommand : Command
{
    public const string CommandText = "qrt bench bvh-comparison";

    private readonly Option<int> _size = CommonOptions.SquareSize("Square image size of every render.", 64);

    private readonly Option<int[]> _qornell = CommonOptions.List("--qornell", "Qornell box sizes N (space-separated).",
        BvhComparisonSettings.DefaultQornellSizes, "N", 8, 4096);

    private readonly Option<int[]> _random = CommonOptions.List("--random", "Scattered random scene sizes N (space-separated).",
        BvhComparisonSettings.DefaultRandomSizes, "N", 1, 8192);

    private readonly BenchReportOptions _report = new(CommandText, "docs/bvh-comparison.md");

    public BenchBvhComparisonCommand() : base("bvh-comparison", "Int/Ray against N for brute force, a BVH (SAH build, counted once per frame) and quantum search, on the Qornell box, Depth Complexity and random scenes.")
    {
        this.AddOptions(_size, _qornell, _random);
        _report.AddTo(this, scenes: false, seed: true, workers: false);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var settings = new BvhComparisonSettings(parse.GetValue(_size), parse.GetValue(_report.Seed), parse.GetValue(_qornell)!, parse.GetValue(_random)!);
        var report = BvhComparisonExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(null, null)));
        return ExitCodes.Success;
    }
}
