using System.Globalization;
using System.Numerics;
using System.Text;
using System.Text.Json;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Export;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>
/// Runs Grover requests as Q# on the QDK full-state simulator: a batch is cut into chunks, each
/// chunk is one call of the Q# operation <c>MeasureGroverBatch</c> on one bridge, and the chunks run
/// on all workers at once (<see cref="BridgeBatches"/>). Whole search schedules go the same way as
/// calls of <c>MeasureGroverSchedules</c>, so QSearch costs one call per batch of searches.
/// Registers are sized per request (see <see cref="SearchRegisters"/>). Measurement outcomes come from the simulator and cannot be seeded.
/// Under a <see cref="NoiseModel"/> other than the ideal one the calls run on the noisy simulator.
/// A batch holding a search wider than <see cref="MaxQubits"/> is refused before any of it is sent.
/// Under a <see cref="DeviceNoiseModel"/> (N a power of two only) a batch is one call of <c>MeasureGroverBatchOnDevice</c>,
/// which sets each gate's rate inside Q#, and the host flips the bits of each measured index by the readout error with
/// <c>readoutRandom</c>, in request order: given the simulator's outcomes, the read indices are reproducible. A schedule
/// stops at its first marked read index, so under a device model schedules run run by run: each round is one batch of
/// the next run of every schedule still searching, read before the next round is sent.
/// </summary>
public sealed class FullStateEngine(BridgePool pool, int maxRequestsPerCall = FullStateEngine.DefaultMaxRequestsPerCall, int? maxQubits = null, bool ownsPool = true, NoiseModel? noise = null,
    DeviceNoiseModel? device = null, SeededRandom? readoutRandom = null) : IScheduleEngine
{
    /// <summary>Large enough to amortise the ~60 ms compile of every QDK call, small enough to spread over workers.</summary>
    public const int DefaultMaxRequestsPerCall = 500;

    public string Name => "fullstate";

    /// <summary>The noise every call runs under.</summary>
    public NoiseModel Noise { get; } = noise ?? NoiseModel.None;

    /// <summary>The device model every call runs under, or null; it replaces <see cref="Noise"/>, which must then be ideal.</summary>
    public DeviceNoiseModel? Device { get; } = DeviceNoiseModel.Alone(device, noise);

    private readonly ReadoutFlips? _readout = ReadoutFlips.For(device, readoutRandom);

    private long _runs;

    /// <summary>Grover runs simulated so far (each request, and each run of a schedule up to its first marked index).</summary>
    public long GroverRuns => Interlocked.Read(ref _runs);

    /// <summary>Qubits a search may use: by default the widest dense state this machine holds (<see cref="SimulatorCapacity"/>).</summary>
    public int MaxQubits { get; } = maxQubits ?? SimulatorCapacity.DefaultMaxQubits(pool.Workers);

    public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests)
    {
        CheckCapacity(requests);
        var measured = Device is { } device ? MeasureOnDevice(device, requests)
            : BridgeBatches.Measure(pool, requests, ChunkLimits.Count(maxRequestsPerCall), QSharpOperations.MeasureGroverBatch, BatchExpression, Noise);
        Interlocked.Add(ref _runs, requests.Count);
        return measured;
    }

    /// <summary>The batch on the device circuit, run with the simulator's global noise off, then each index's n bits read with the readout error.</summary>
    private int[] MeasureOnDevice(DeviceNoiseModel device, IReadOnlyList<GroverRequest> requests)
    {
        foreach (var request in requests)
            if (!BitOperations.IsPow2(request.Marked.Count))
                throw new ArgumentException($"under a device model the full-state search runs N a power of two only, got N = {request.Marked.Count}", nameof(requests));
        var measured = BridgeBatches.Measure(pool, requests, ChunkLimits.Count(maxRequestsPerCall), QSharpOperations.MeasureGroverBatchOnDevice,
            chunk => DeviceBatchExpression(device, chunk), NoiseModel.None, noisyReadout: true);
        if (_readout is not null)
            for (var k = 0; k < measured.Length; k++) measured[k] = _readout.ReadBits(measured[k], SearchRegisters.For(requests[k].Marked.Count).IndexQubits);
        return measured;
    }

    public IReadOnlyList<int[]> MeasureSchedules(IReadOnlyList<IReadOnlyList<GroverRequest>> schedules)
    {
        for (var k = 0; k < schedules.Count; k++)
            if (schedules[k].Count == 0 || schedules[k].Any(r => r.Marked != schedules[k][0].Marked))
                throw new ArgumentException($"schedule {k} must hold at least one run, all over one marked set", nameof(schedules));
        CheckCapacity(schedules.Select(s => s[0]).ToArray());
        if (Device is not null) return MeasureSchedulesRunByRun(schedules);
        var measured = BridgeBatches.Run(pool, schedules, maxRequestsPerCall, _ => 1, double.PositiveInfinity, ScheduleExpression, ParseSchedules, Noise);
        Interlocked.Add(ref _runs, measured.Sum(m => (long)m.Length));
        return measured;
    }

    /// <summary>Round k measures run k of every schedule not yet stopped, through <see cref="Measure"/>, so that each stop is decided on the read index.</summary>
    private int[][] MeasureSchedulesRunByRun(IReadOnlyList<IReadOnlyList<GroverRequest>> schedules)
    {
        var outcomes = schedules.Select(_ => new List<int>()).ToArray();
        var searching = Enumerable.Range(0, schedules.Count).ToList();
        for (var run = 0; searching.Count > 0; run++)
        {
            var read = Measure(searching.Select(k => schedules[k][run]).ToArray());
            var next = new List<int>();
            for (var j = 0; j < searching.Count; j++)
            {
                var k = searching[j];
                outcomes[k].Add(read[j]);
                if (!IsHit(schedules[k][0].Marked, read[j]) && run + 1 < schedules[k].Count) next.Add(k);
            }
            searching = next;
        }
        return outcomes.Select(o => o.ToArray()).ToArray();
    }

    /// <summary>Whether a read index is marked; under noise an index can read past N, which is no hit.</summary>
    private static bool IsHit(MarkedSet marked, int index) => index >= 0 && index < marked.Count && marked.Contains(index);

    private void CheckCapacity(IReadOnlyList<GroverRequest> requests)
    {
        if (requests.Count == 0) return;
        // Auxiliaries only ever hold ANDs of index bits and are cleared after every gate: the state spans the index register.
        var widest = requests.Max(r => r.Marked.Count);
        var registers = SearchRegisters.For(widest);
        SimulatorCapacity.Check($"a search over N = {widest} indices", registers.PeakQubits, registers.IndexQubits, MaxQubits);
    }

    /// <summary>The runs of each schedule up to its first marked index, each index checked against its N.</summary>
    private int[][] ParseSchedules(IReadOnlyList<IReadOnlyList<GroverRequest>> schedules, string value)
    {
        var measured = JsonSerializer.Deserialize<int[][]>(value) ?? throw new BridgeException($"{QSharpOperations.MeasureGroverSchedules} returned no value");
        if (measured.Length != schedules.Count)
            throw new BridgeException($"{QSharpOperations.MeasureGroverSchedules} returned {measured.Length} outcome lists for {schedules.Count} searches");
        for (var k = 0; k < schedules.Count; k++)
        {
            var runs = schedules[k];
            var outcomes = measured[k];
            var firstMarked = Array.FindIndex(outcomes, i => IsHit(runs[0].Marked, i));
            var expected = firstMarked < 0 ? runs.Count : firstMarked + 1;
            if (outcomes.Length != expected)
                throw new BridgeException($"{QSharpOperations.MeasureGroverSchedules} returned {outcomes.Length} outcomes for a schedule of {runs.Count} runs, expected {expected}");
            foreach (var index in outcomes) BridgeBatches.CheckIndex(QSharpOperations.MeasureGroverSchedules, index, runs[0], !Noise.IsNoiseless);
        }
        return measured;
    }

    /// <summary>The Q# call for a batch: <c>MeasureGroverBatch([(N, [marked…], r), …])</c>, or the same call of another operation with that signature.</summary>
    public static string BatchExpression(IReadOnlyList<GroverRequest> requests) => BatchExpression(requests, QSharpOperations.MeasureGroverBatch);

    /// <inheritdoc cref="BatchExpression(IReadOnlyList{GroverRequest})"/>
    public static string BatchExpression(IReadOnlyList<GroverRequest> requests, string operation) =>
        Call(operation, requests, r => r, (text, r) => text.Append(r.Iterations.ToString(CultureInfo.InvariantCulture)));

    /// <summary>The Q# call for a batch under a device model: <c>MeasureGroverBatchOnDevice(p1, p2, [(N, [marked…], r), …])</c>.</summary>
    public static string DeviceBatchExpression(DeviceNoiseModel device, IReadOnlyList<GroverRequest> requests) =>
        Call(QSharpOperations.MeasureGroverBatchOnDevice, requests, r => r, (text, r) => text.Append(r.Iterations.ToString(CultureInfo.InvariantCulture)),
            $"{ExportNumber.QSharpDouble(device.OneQubit)}, {ExportNumber.QSharpDouble(device.TwoQubit)}, ");

    /// <summary>The Q# call for schedules: <c>MeasureGroverSchedules([(N, [marked…], [r₁, r₂, …]), …])</c>.</summary>
    public static string ScheduleExpression(IReadOnlyList<IReadOnlyList<GroverRequest>> schedules) =>
        Call(QSharpOperations.MeasureGroverSchedules, schedules, s => s[0], (text, s) => IntArray(text, s.Select(r => r.Iterations).ToArray()));

    /// <summary>
    /// <c>operation(leading[(N, [marked…], last), …])</c>: one tuple per item, <paramref name="last"/> writing its last element,
    /// after the arguments in <paramref name="leading"/> (empty, or ending in ", ").
    /// </summary>
    private static string Call<T>(string operation, IReadOnlyList<T> items, Func<T, GroverRequest> request, Func<StringBuilder, T, StringBuilder> last, string leading = "")
    {
        var text = new StringBuilder(operation).Append('(').Append(leading).Append('[');
        for (var k = 0; k < items.Count; k++)
        {
            if (k > 0) text.Append(", ");
            var marked = request(items[k]).Marked;
            text.Append('(').Append(marked.Count.ToString(CultureInfo.InvariantCulture)).Append(", ");
            IntArray(text, marked.Indices.ToArray()).Append(", ");
            last(text, items[k]).Append(')');
        }
        return text.Append("])").ToString();
    }

    /// <summary>A Q# Int[] literal; an empty one is written <c>[0, size = 0]</c>, as Q# cannot infer the type of <c>[]</c> here.</summary>
    private static StringBuilder IntArray(StringBuilder text, IReadOnlyList<int> values)
    {
        if (values.Count == 0) return text.Append("[0, size = 0]");
        text.Append('[');
        for (var i = 0; i < values.Count; i++)
        {
            if (i > 0) text.Append(", ");
            text.Append(values[i].ToString(CultureInfo.InvariantCulture));
        }
        return text.Append(']');
    }

    public BridgePool Pool => pool;

    /// <summary>Stops the engine's bridges, unless the pool is shared (<c>ownsPool</c> false).</summary>
    public void Dispose()
    {
        if (ownsPool) pool.Dispose();
    }
}
