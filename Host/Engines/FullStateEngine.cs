using System.Globalization;
using System.Text;
using System.Text.Json;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Noise;
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
/// </summary>
public sealed class FullStateEngine(BridgePool pool, int maxRequestsPerCall = FullStateEngine.DefaultMaxRequestsPerCall, int? maxQubits = null, bool ownsPool = true, NoiseModel? noise = null) : IScheduleEngine
{
    /// <summary>Large enough to amortise the ~60 ms compile of every QDK call, small enough to spread over workers.</summary>
    public const int DefaultMaxRequestsPerCall = 500;

    public string Name => "fullstate";

    /// <summary>The noise every call runs under.</summary>
    public NoiseModel Noise { get; } = noise ?? NoiseModel.None;

    private long _runs;

    /// <summary>Grover runs simulated so far (each request, and each run of a schedule up to its first marked index).</summary>
    public long GroverRuns => Interlocked.Read(ref _runs);

    /// <summary>Qubits a search may use: by default the widest dense state this machine holds (<see cref="SimulatorCapacity"/>).</summary>
    public int MaxQubits { get; } = maxQubits ?? SimulatorCapacity.DefaultMaxQubits(pool.Workers);

    public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests)
    {
        CheckCapacity(requests);
        var measured = BridgeBatches.Measure(pool, requests, ChunkLimits.Count(maxRequestsPerCall), QSharpOperations.MeasureGroverBatch, BatchExpression, Noise);
        Interlocked.Add(ref _runs, requests.Count);
        return measured;
    }

    public IReadOnlyList<int[]> MeasureSchedules(IReadOnlyList<IReadOnlyList<GroverRequest>> schedules)
    {
        for (var k = 0; k < schedules.Count; k++)
            if (schedules[k].Count == 0 || schedules[k].Any(r => r.Marked != schedules[k][0].Marked))
                throw new ArgumentException($"schedule {k} must hold at least one run, all over one marked set", nameof(schedules));
        CheckCapacity(schedules.Select(s => s[0]).ToArray());
        var measured = BridgeBatches.Run(pool, schedules, maxRequestsPerCall, _ => 1, double.PositiveInfinity, ScheduleExpression, ParseSchedules, Noise);
        Interlocked.Add(ref _runs, measured.Sum(m => (long)m.Length));
        return measured;
    }

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
            var firstMarked = Array.FindIndex(outcomes, i => i >= 0 && i < runs[0].Marked.Count && runs[0].Marked.Contains(i));
            var expected = firstMarked < 0 ? runs.Count : firstMarked + 1;
            if (outcomes.Length != expected)
                throw new BridgeException($"{QSharpOperations.MeasureGroverSchedules} returned {outcomes.Length} outcomes for a schedule of {runs.Count} runs, expected {expected}");
            foreach (var index in outcomes) BridgeBatches.CheckIndex(QSharpOperations.MeasureGroverSchedules, index, runs[0], Noise);
        }
        return measured;
    }

    /// <summary>The Q# call for a batch: <c>MeasureGroverBatch([(N, [marked…], r), …])</c>, or the same call of another operation with that signature.</summary>
    public static string BatchExpression(IReadOnlyList<GroverRequest> requests) => BatchExpression(requests, QSharpOperations.MeasureGroverBatch);

    /// <inheritdoc cref="BatchExpression(IReadOnlyList{GroverRequest})"/>
    public static string BatchExpression(IReadOnlyList<GroverRequest> requests, string operation) =>
        Call(operation, requests, r => r, (text, r) => text.Append(r.Iterations.ToString(CultureInfo.InvariantCulture)));

    /// <summary>The Q# call for schedules: <c>MeasureGroverSchedules([(N, [marked…], [r₁, r₂, …]), …])</c>.</summary>
    public static string ScheduleExpression(IReadOnlyList<IReadOnlyList<GroverRequest>> schedules) =>
        Call(QSharpOperations.MeasureGroverSchedules, schedules, s => s[0], (text, s) => IntArray(text, s.Select(r => r.Iterations).ToArray()));

    /// <summary><c>operation([(N, [marked…], last), …])</c>: one tuple per item, <paramref name="last"/> writing its last element.</summary>
    private static string Call<T>(string operation, IReadOnlyList<T> items, Func<T, GroverRequest> request, Func<StringBuilder, T, StringBuilder> last)
    {
        var text = new StringBuilder(operation).Append("([");
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
