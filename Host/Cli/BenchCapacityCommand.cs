using System.CommandLine;
using System.Globalization;
using System.Text;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Cli;

/// <summary>`bench capacity`: the simulator's memory per amplitude, the figure behind the full-state engines' --max-qubits default.</summary>
public sealed class BenchCapacityCommand : Command
{
    private readonly Option<int[]> _qubits = new("--qubits")
    {
        Description = "Widths of the dense states measured (space-separated, 1..25; 25 takes about 15 s and 2.5 GB).",
        DefaultValueFactory = _ => [16, 18, 20, 22, 24],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<FileInfo?> _output = new("--output", "-o")
    {
        Description = "Write the Markdown report here (e.g. docs/simulator-capacity.md). It replaces only a report this command wrote before. Default: the report is printed only.",
    };

    public BenchCapacityCommand() : base("capacity", "Memory of the QDK full-state simulator per amplitude of a dense state, measured per width in a fresh bridge (Linux).")
    {
        Options.Add(_qubits);
        Options.Add(_output);
        _qubits.Validators.Add(r =>
        {
            if ((r.GetValueOrDefault<int[]>() ?? []).Any(q => q is < 1 or > 25)) r.AddError("--qubits: each width must be between 1 and 25 (26 exhausts the simulator's 4 GiB WebAssembly heap)");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var report = new GeneratedReport(parse.GetValue(_output)?.FullName, GeneratedReport.MarkdownMarker("qrt bench capacity"));
        report.EnsureWritable();
        string versions;
        using (var bridge = new QSharpBridge())
        {
            var v = bridge.Version();
            versions = MachineDescription.Describe(v["qsharp"]?.GetValue<string>(), v["node"]?.GetValue<string>());
        }
        var rows = new List<SimulatorMemoryBenchmark.Row>();
        foreach (var qubits in parse.GetValue(_qubits)!)
        {
            Console.Error.WriteLine($"measuring a dense state of {qubits} qubits");
            rows.Add(SimulatorMemoryBenchmark.Measure(qubits));
        }
        var text = Markdown(rows, versions, string.Join(' ', Environment.GetCommandLineArgs().Skip(1)));
        Console.WriteLine(text);
        report.Write(text);
        return 0;
    }

    private static string Markdown(List<SimulatorMemoryBenchmark.Row> rows, string machine, string arguments)
    {
        static string Mb(long bytes) => (bytes / 1e6).ToString("0", CultureInfo.InvariantCulture);
        var text = new StringBuilder();
        text.AppendLine("# Simulator capacity: memory per amplitude");
        text.AppendLine();
        text.AppendLine("Each width q runs the Q# operation `MeasureDenseState(q)` (every one of the 2^q amplitudes nonzero, entangled) in a fresh");
        text.AppendLine("bridge process; the growth of the process's peak resident memory over its peak after a 1-qubit run of the same program,");
        text.AppendLine("divided by 2^q, is the simulator's memory per amplitude (the amplitude map's growth by doubling included). Below about 20");
        text.AppendLine("qubits the figure is dominated by the granularity in which the WebAssembly heap grows.");
        text.AppendLine();
        text.AppendLine("| qubits | amplitudes | peak after 1 qubit, MB | peak, MB | bytes per amplitude | wall time |");
        text.AppendLine("|---|---|---|---|---|---|");
        foreach (var r in rows)
            text.AppendLine(string.Create(CultureInfo.InvariantCulture,
                $"| {r.Qubits} | {r.Amplitudes:N0} | {Mb(r.IdleBytes)} | {Mb(r.PeakBytes)} | {r.BytesPerAmplitude:0.0} | {r.Elapsed.TotalSeconds:0.00} s |"));
        text.AppendLine();
        text.AppendLine(string.Create(CultureInfo.InvariantCulture,
            $"The full-state engines budget {SimulatorCapacity.BytesPerAmplitude:0} bytes per amplitude in a WebAssembly heap of 4 GiB per worker: at most {SimulatorCapacity.MaxQubitsFor(SimulatorCapacity.WebAssemblyHeapBytes)} dense qubits per bridge; on this machine with the default workers, `--max-qubits` defaults to {SimulatorCapacity.DefaultMaxQubits(BridgePool.DefaultWorkers)}."));
        text.AppendLine("A dense state of 26 qubits ends the bridge with a WebAssembly `RuntimeError: unreachable` (out of heap), which is why `--qubits` stops at 25.");
        text.AppendLine();
        text.AppendLine($"Machine: {machine}.");
        text.AppendLine($"Command: `dotnet run --project Host -c Release -- {arguments}`.");
        return text.ToString();
    }
}
