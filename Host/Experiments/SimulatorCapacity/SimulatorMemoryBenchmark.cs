using System.Diagnostics;
using System.Globalization;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// Measures the full-state simulator's memory per amplitude: a fresh bridge per width runs
/// <c>MeasureDenseState</c> (all 2^q amplitudes nonzero) and the growth of the bridge process's
/// peak resident memory (Linux <c>VmHWM</c>) is divided by 2^q. The growth is taken over the peak
/// after a 1-qubit run, so that compiling and running the program once is not counted.
/// </summary>
public static class SimulatorMemoryBenchmark
{
    public sealed record Row(int Qubits, long IdleBytes, long PeakBytes, TimeSpan Elapsed)
    {
        public double Amplitudes => Math.Pow(2, Qubits);

        public double BytesPerAmplitude => (PeakBytes - IdleBytes) / Amplitudes;
    }

    public static Row Measure(int qubits, BridgeOptions? options = null)
    {
        using var bridge = new QSharpBridge(options ?? new BridgeOptions());
        bridge.Run($"{QSharpOperations.MeasureDenseState}(1)");
        var pid = bridge.ProcessId ?? throw new BridgeException("the bridge is not running after start-up");
        var idle = PeakResidentBytes(pid);
        var clock = Stopwatch.StartNew();
        bridge.Run($"{QSharpOperations.MeasureDenseState}({qubits.ToString(CultureInfo.InvariantCulture)})");
        var elapsed = clock.Elapsed;
        return new Row(qubits, idle, PeakResidentBytes(pid), elapsed);
    }

    /// <summary>Peak resident memory of a process, from <c>/proc/PID/status</c>.</summary>
    public static long PeakResidentBytes(int pid)
    {
        var path = $"/proc/{pid.ToString(CultureInfo.InvariantCulture)}/status";
        if (!File.Exists(path)) throw new PlatformNotSupportedException($"{path} does not exist: measuring a process's peak memory needs Linux");
        var line = File.ReadLines(path).FirstOrDefault(l => l.StartsWith("VmHWM:", StringComparison.Ordinal))
            ?? throw new PlatformNotSupportedException($"{path} has no VmHWM line");
        var kilobytes = long.Parse(line["VmHWM:".Length..].Trim().Split(' ')[0], CultureInfo.InvariantCulture);
        return kilobytes * 1024;
    }
}
