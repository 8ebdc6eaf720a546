using System.CommandLine;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`estimate oracle-sweep`: options → <see cref="OracleSweepSettings"/> → <see cref="OracleSweepExperiment"/> (docs/oracle-sweep.md).</summary>
public sealed class EstimateOracleSweepCommand : Command
{
    public const string CommandText = "qrt estimate oracle-sweep";

    private readonly Option<int[]> _primitives = CommonOptions.List("--primitives", $"Primitive counts N of the sweep over N, on a {EstimateSweep.DefaultCoordinateBits}-bit grid (space-separated).",
        EstimateSweep.Primitives.ToArray(), "N", 1, 4096);

    private readonly Option<int[]> _bits = CommonOptions.List("--bits", $"Coordinate bits of the sweep over the grid, at N = {EstimateSweep.DefaultPrimitives} (space-separated).",
        EstimateSweep.CoordinateBits.ToArray(), "count", 2, 16);

    private readonly Option<int[]> _ablation = CommonOptions.List("--ablation", "Primitive counts at which each change of the construction is also measured on its own (space-separated).",
        [4, EstimateSweep.DefaultPrimitives], "N", 1, 4096);

    private readonly Option<FileInfo?> _output = CommonOptions.ReportOutput("Write the Markdown report here (e.g. docs/oracle-sweep.md). It replaces only a report this command wrote before. Default: the report is printed only.");

    private readonly EstimateOptions _options = new();

    public EstimateOracleSweepCommand() : base("oracle-sweep", "The oracle's estimates against the number of primitives (4..512) and the coordinate bits (2..8), before and after the compact construction, as Markdown.")
    {
        Aliases.Add("sweep"); // its earlier name: scripts that use it still work
        this.AddOptions(_primitives, _bits, _ablation, _output);
        _options.AddTo(this, withFormat: false);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = new ReportWriter(parse.GetValue(_output)?.FullName, CommandText);
        writer.EnsureWritable();
        var settings = new OracleSweepSettings(parse.GetValue(_primitives)!, parse.GetValue(_bits)!, parse.GetValue(_ablation)!,
            _options.QubitModels(parse), WithCircuits: !parse.GetValue(_options.NoCircuit), parse.GetValue(_options.Workers));
        var report = OracleSweepExperiment.Run(settings, Console.Error.WriteLine);
        var versions = ToolVersions.Detect();
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(versions.QsharpLang, versions.Node)));
        return ExitCodes.Success;
    }
}
