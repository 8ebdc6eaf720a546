using System.Globalization;

namespace QuantumRayTracing.Engines;

/// <summary>
/// What the QDK's full-state simulator can hold on this machine, and the check every full-state
/// engine runs on a batch before any of it reaches a simulator. The simulator is sparse (it stores
/// nonzero amplitudes only) and runs inside WebAssembly, whose 32-bit heap stops at 4 GiB per
/// bridge process; each worker is one such process.
/// </summary>
public static class SimulatorCapacity
{
    /// <summary>
    /// Peak heap bytes per stored amplitude. Measured with a dense, entangled state of q qubits in one
    /// bridge: about 65 bytes at q = 25 (2.2 GB above the idle process), more while the amplitude map
    /// grows; q = 26 ran out of the WebAssembly heap. 80 covers the growth.
    /// </summary>
    public const double BytesPerAmplitude = 80;

    /// <summary>The WebAssembly heap of one bridge: 32-bit addresses, 4 GiB.</summary>
    public const long WebAssemblyHeapBytes = 4L << 30;

    /// <summary>Memory this process may use: the machine's, or the container's limit.</summary>
    public static long MachineBytes => GC.GetGCMemoryInfo().TotalAvailableMemoryBytes;

    /// <summary>
    /// Heap one bridge may fill when <paramref name="workers"/> run at once: the WebAssembly heap,
    /// or an equal share of half the machine's memory if that is smaller.
    /// </summary>
    public static long BytesPerWorker(int workers, long machineBytes) =>
        Math.Min(WebAssemblyHeapBytes, machineBytes / 2 / Math.Max(1, workers));

    /// <summary>Heap for a state of 2^<paramref name="superposedQubits"/> amplitudes.</summary>
    public static double Bytes(int superposedQubits) => Math.Pow(2, superposedQubits) * BytesPerAmplitude;

    /// <summary>The widest dense state that fits <see cref="BytesPerWorker"/>: the default of --max-qubits on full-state engines.</summary>
    public static int DefaultMaxQubits(int workers) => MaxQubitsFor(BytesPerWorker(workers, MachineBytes));

    public static int MaxQubitsFor(long bytes)
    {
        var qubits = 0;
        while (Bytes(qubits + 1) <= bytes) qubits++;
        return qubits;
    }

    /// <summary>
    /// Throws a <see cref="SimulatorLimitException"/> when <paramref name="qubits"/> (of which
    /// <paramref name="superposedQubits"/> can hold a dense superposition) exceed <paramref name="maxQubits"/>.
    /// </summary>
    public static void Check(string what, int qubits, int superposedQubits, int maxQubits)
    {
        if (qubits <= maxQubits) return;
        throw new SimulatorLimitException(string.Create(CultureInfo.InvariantCulture,
            $"{what} needs {qubits} qubits (2^{superposedQubits} amplitudes, about {Describe(Bytes(superposedQubits))} of simulator memory per worker), more than the limit of {maxQubits} (--max-qubits; the default is the widest state this machine holds: a WebAssembly heap of at most 4 GiB per worker)"));
    }

    public static string Describe(double bytes) => bytes switch
    {
        >= 1 << 30 => (bytes / (1 << 30)).ToString("0.0", CultureInfo.InvariantCulture) + " GiB",
        >= 1 << 20 => (bytes / (1 << 20)).ToString("0.0", CultureInfo.InvariantCulture) + " MiB",
        _ => (bytes / (1 << 10)).ToString("0.0", CultureInfo.InvariantCulture) + " KiB",
    };
}
