using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench device-noise`: options → <see cref="DeviceNoiseSettings"/> → <see cref="DeviceNoiseExperiment"/> (docs/device-noise.md).</summary>
public sealed class BenchDeviceNoiseCommand : Command
{
    public const string CommandText = "qrt bench device-noise";

    private readonly Option<int> _size = CommonOptions.SquareSize("Square image size of the renders.", 128);

    private readonly BenchReportOptions _report = new(CommandText, "docs/device-noise.md");

    public BenchDeviceNoiseCommand() : base("device-noise", "A device noise model (one-qubit and multi-qubit gate rates, readout error) on the searches: the analytic model against the lookup circuit evolved exactly, and Qornell-64 rendered under device models on both oracles, with and without noise-aware passes.")
    {
        this.AddOptions(_size);
        _report.AddTo(this, workers: false);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var settings = new DeviceNoiseSettings(_report.Load(parse, "qornell-64"), parse.GetValue(_size), parse.GetValue(_report.Seed));
        var report = DeviceNoiseExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(null, null)));
        return ExitCodes.Success;
    }
}
