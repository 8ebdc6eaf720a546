using QuantumRayTracing.Search;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// What a recorded frame costs on fault-tolerant machines: each pass and the whole frame
/// (<see cref="FramePart"/>), from the price of each run's (shape, r) summed over the runs.
/// </summary>
/// <param name="Budget">The frame budget and its split over the quantum runs.</param>
/// <param name="Models">The qubit models, in the order of every part's physical lists.</param>
/// <param name="Qpus">K, the quantum processors of the parallel runtime.</param>
/// <param name="Passes">One part per pass that made Grover runs, in render order.</param>
/// <param name="Total">The frame.</param>
public sealed record FrameCost(FrameBudget Budget, IReadOnlyList<QubitModel> Models, int Qpus, IReadOnlyList<FramePart> Passes, FramePart Total)
{
    /// <summary>The frame budget's split for a recording: ε shared by its runs with r ≥ 1.</summary>
    public static FrameBudget BudgetFor(FrameRecording recording, double frameBudget) =>
        new(frameBudget, recording.Runs.LongCount(r => r.Iterations > 0));

    public static FrameCost Of(FrameRecording recording, IReadOnlyDictionary<(OracleShape Shape, int Iterations), RunPrice> prices,
        IReadOnlyList<QubitModel> models, FrameBudget budget, int qpus)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(qpus, 1);
        var parts = recording.Passes
            .Select(pass => Part(pass, recording.Runs.Where(r => r.Pass == pass).ToArray(), prices, models.Count, qpus))
            .Where(p => p.QuantumRuns + p.ClassicalDraws > 0)
            .ToArray();
        return new FrameCost(budget, models, qpus, parts, Part("total", recording.Runs, prices, models.Count, qpus));
    }

    private static FramePart Part(string name, IReadOnlyList<RecordedRun> runs, IReadOnlyDictionary<(OracleShape, int), RunPrice> prices, int modelCount, int qpus)
    {
        var queries = default(SearchCost);
        foreach (var run in runs) queries += SearchCost.OfGroverRun(run.Iterations);
        var quantum = runs.Where(r => r.Iterations > 0).ToArray();
        var logical = new LogicalCounts(0, 0, 0, 0, 0, 0, 0);
        foreach (var run in quantum)
        {
            var l = prices[run.Key].Logical;
            logical = new LogicalCounts(Math.Max(logical.Qubits, l.Qubits), logical.T + l.T, logical.Rotations + l.Rotations,
                logical.RotationDepth + l.RotationDepth, logical.Ccz + l.Ccz, logical.Ccix + l.Ccix, logical.Measurements + l.Measurements);
        }
        FramePhysical[] Physical(Func<RunPrice, IReadOnlyList<PhysicalEstimate>> policy) => Enumerable.Range(0, modelCount).Select(m =>
        {
            PhysicalEstimate Of(RecordedRun run) => policy(prices[run.Key])[m];
            if (quantum.Length == 0) return new FramePhysical(0, 0, 0, 0, 0, 0);
            var parallel = quantum.GroupBy(r => r.Batch).Sum(batch => Makespan(batch.Select(r => Of(r).RuntimeNanoseconds), qpus));
            return new FramePhysical(
                quantum.Max(r => Of(r).PhysicalQubits),
                quantum.Sum(r => Of(r).RuntimeNanoseconds),
                parallel,
                quantum.Min(r => Of(r).CodeDistance),
                quantum.Max(r => Of(r).CodeDistance),
                quantum.Sum(r => Of(r).Errors?.FailureBound ?? double.NaN));
        }).ToArray();
        return new FramePart(name, quantum.Length, runs.Count - quantum.Length, queries, logical, Physical(p => p.Split), Physical(p => p.Alone));
    }

    /// <summary>
    /// The time independent jobs take on <paramref name="processors"/> machines when each job, longest
    /// first, goes to the machine free earliest (LPT list scheduling: within 4/3 of the optimum, and
    /// exact when there are no more jobs than machines).
    /// </summary>
    public static double Makespan(IEnumerable<double> durations, int processors)
    {
        var loads = new PriorityQueue<int, double>();
        var finish = new double[processors];
        for (var k = 0; k < processors; k++) loads.Enqueue(k, 0);
        foreach (var duration in durations.OrderDescending())
        {
            var machine = loads.Dequeue();
            finish[machine] += duration;
            loads.Enqueue(machine, finish[machine]);
        }
        return finish.Max();
    }
}
