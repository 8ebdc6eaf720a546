using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Reports;
using static System.FormattableString;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench simulator-capacity`: the simulator's memory per amplitude, the figure behind the full-state engines' --max-qubits default (docs/simulator-capacity.md).</summary>
public static class SimulatorCapacityExperiment
{
    public const string Title = "Simulator capacity: memory per amplitude";

    public static Report Run(SimulatorCapacitySettings settings, Action<string> progress)
    {
        var rows = new List<SimulatorMemoryBenchmark.Row>();
        foreach (var qubits in settings.Qubits)
        {
            progress($"measuring a dense state of {qubits} qubits");
            rows.Add(SimulatorMemoryBenchmark.Measure(qubits));
        }

        static string Mb(long bytes) => Invariant($"{bytes / 1e6:0}");
        var report = new Report(Title);
        report.Text("""
            Each width q runs the Q# operation `MeasureDenseState(q)` (every one of the 2^q amplitudes nonzero, entangled) in a fresh
            bridge process; the growth of the process's peak resident memory over its peak after a 1-qubit run of the same program,
            divided by 2^q, is the simulator's memory per amplitude (the amplitude map's growth by doubling included). Below about 20
            qubits the figure is dominated by the granularity in which the WebAssembly heap grows.
            """);
        var table = new TextTable("widths", ["qubits", "amplitudes", "peak after 1 qubit, MB", "peak, MB", "bytes per amplitude", "wall time"]);
        foreach (var r in rows)
            table.Row(Invariant($"{r.Qubits}"), Invariant($"{r.Amplitudes:N0}"), Mb(r.IdleBytes), Mb(r.PeakBytes), Invariant($"{r.BytesPerAmplitude:0.0}"), Invariant($"{r.Elapsed.TotalSeconds:0.00} s"));
        report.Table(table);
        report.Text(Invariant($"""
            The full-state engines budget {SimulatorCapacity.BytesPerAmplitude:0} bytes per amplitude in a WebAssembly heap of 4 GiB per worker: at most {SimulatorCapacity.MaxQubitsFor(SimulatorCapacity.WebAssemblyHeapBytes)} dense qubits per bridge; on this machine with the default workers, `--max-qubits` defaults to {SimulatorCapacity.DefaultMaxQubits(BridgePool.DefaultWorkers)}.
            A dense state of 26 qubits ends the bridge with a WebAssembly `RuntimeError: unreachable` (out of heap), which is why `--qubits` stops at 25.
            """));
        return report;
    }
}
