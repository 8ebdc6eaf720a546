using System.CommandLine;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench simulator-capacity`: options → <see cref="SimulatorCapacitySettings"/> → <see cref="SimulatorCapacityExperiment"/> (docs/simulator-capacity.md).</summary>
public sealed class BenchSimulatorCapacityCommand : Command
{
    public const string CommandText = "qrt bench simulator-capacity";

    private readonly Option<int[]> _qubits = CommonOptions.List("--qubits", "Widths of the dense states measured (space-separated, 1..25; 25 takes about 15 s and 2.5 GB).",
        [16, 18, 20, 22, 24], "width", 1, 25, " (26 exhausts the simulator's 4 GiB WebAssembly heap)");

    private readonly BenchReportOptions _report = new(CommandText, "docs/simulator-capacity.md");

    public BenchSimulatorCapacityCommand() : base("simulator-capacity", "Memory of the QDK full-state simulator per amplitude of a dense state, measured per width in a fresh bridge (Linux).")
    {
        Aliases.Add("capacity"); // its earlier name: scripts that use it still work
        Options.Add(_qubits);
        // Each width runs in a bridge process of its own on this machine, whose memory is the measure: no --workers, no --cluster.
        _report.AddTo(this, scenes: false, seed: false, workers: false);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var report = SimulatorCapacityExperiment.Run(new SimulatorCapacitySettings(parse.GetValue(_qubits)!), Console.Error.WriteLine);
        var tools = ToolVersions.Detect();
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(tools.QsharpLang, tools.Node)));
        return ExitCodes.Success;
    }
}
