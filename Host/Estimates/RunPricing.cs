using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// Prices a recorded frame's runs: one Resource Estimator job per distinct (oracle shape, r), on the
/// shape's example ray (<see cref="FrameRecording.Examples"/>), a QSearch run circuit
/// (<see cref="EstimatedCircuits.SearchRun"/>: prepare, r Grover iterations, measure), each job on
/// every model twice: at the per-run budget, then at the frame budget.
/// </summary>
public static class RunPricing
{
    /// <summary>The estimator's model list: every model at ε / R, then every model at ε.</summary>
    public static IReadOnlyList<QubitModel> Models(IReadOnlyList<QubitModel> models, FrameBudget budget) =>
        [.. models.Select(m => m with { Budget = budget.PerRun }), .. models.Select(m => m with { Budget = budget.Frame })];

    /// <summary>The distinct (shape, r) of the runs, in first-seen order, and the estimator job of each.</summary>
    public static IReadOnlyList<((OracleShape Shape, int Iterations) Key, (EstimatedCircuit Circuit, EstimateSubject Subject) Job)> Jobs(
        FrameRecording recording, OracleConstruction construction) =>
        recording.Runs.Select(r => r.Key).Distinct()
            .Select(key => (key, (EstimatedCircuits.SearchRun, new EstimateSubject(recording.Examples[key.Shape] with { Construction = construction }, key.Iterations, key.Shape.ToString()))))
            .ToArray();

    /// <summary>The price of each key from its job's estimate on <see cref="Models"/> of <paramref name="modelCount"/> models.</summary>
    public static IReadOnlyDictionary<(OracleShape Shape, int Iterations), RunPrice> Prices(
        IReadOnlyList<(OracleShape Shape, int Iterations)> keys, IReadOnlyList<CircuitEstimate> estimates, int modelCount)
    {
        if (keys.Count != estimates.Count) throw new ArgumentException($"{estimates.Count} estimates for {keys.Count} run shapes");
        var prices = new Dictionary<(OracleShape, int), RunPrice>();
        for (var k = 0; k < keys.Count; k++)
        {
            var physical = estimates[k].Physical;
            if (physical.Count != 2 * modelCount) throw new ArgumentException($"an estimate has {physical.Count} physical results for 2 x {modelCount} models");
            prices[keys[k]] = new RunPrice(estimates[k].Logical, physical.Take(modelCount).ToArray(), physical.Skip(modelCount).ToArray());
        }
        return prices;
    }
}
