using QuantumRayTracing.Bridge;
using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// Prices a recorded frame's runs. A run's circuit is a QSearch run (<see cref="EstimatedCircuits.SearchRun"/>:
/// prepare, r Grover iterations with the gate-level oracle, measure), which depends only on the
/// oracle's shape and r. So: the Resource Estimator traces each distinct shape's circuit on its
/// example ray with r = 1 and r = 2; the counts for any r follow exactly
/// (<see cref="LogicalCounts.Extrapolate"/>); and each distinct set of counts is priced once on every
/// model, at the per-run budget and at the frame budget (<see cref="ResourceEstimator.EstimateCounts"/>).
/// </summary>
public static class RunPricing
{
    /// <summary>The estimator's model list for pricing: every model at ε / R, then every model at ε.</summary>
    public static IReadOnlyList<QubitModel> Models(IReadOnlyList<QubitModel> models, FrameBudget budget) =>
        [.. models.Select(m => m with { Budget = budget.PerRun }), .. models.Select(m => m with { Budget = budget.Frame })];

    /// <summary>The price of every (shape, r) with r ≥ 1 among the runs, and how many estimator jobs it took.</summary>
    public static (IReadOnlyDictionary<(OracleShape Shape, int Iterations), RunPrice> Prices, int Jobs) Price(
        FrameRecording recording, OracleConstruction construction, IReadOnlyList<QubitModel> models, FrameBudget budget, BridgePool pool, Action? onDone = null)
    {
        var keys = recording.Runs.Where(r => r.Iterations > 0).Select(r => r.Key).Distinct().ToArray();
        var shapes = keys.Select(k => k.Shape).Distinct().ToArray();

        // Logical counts only: the model and budget of this pass do not matter.
        var tracer = new ResourceEstimator(pool, [models[0]], withCircuits: false);
        var traced = tracer.Estimate(shapes.SelectMany(shape => new[] { 1, 2 }.Select(r =>
            (EstimatedCircuits.SearchRun, new EstimateSubject(recording.Examples[shape] with { Construction = construction }, r, shape.ToString())))).ToArray(), onDone);
        var counts = keys.ToDictionary(k => k, k =>
        {
            var s = Array.IndexOf(shapes, k.Shape);
            return LogicalCounts.Extrapolate(traced[2 * s].Logical, traced[2 * s + 1].Logical, k.Iterations);
        });

        var distinct = counts.Values.Distinct().ToArray();
        var priced = new ResourceEstimator(pool, Models(models, budget), withCircuits: false).EstimateCounts(distinct, onDone);
        var byCounts = distinct.Zip(priced).ToDictionary(p => p.First, p => p.Second);
        var prices = keys.ToDictionary(k => k, k =>
        {
            var physical = byCounts[counts[k]];
            return new RunPrice(counts[k], physical.Take(models.Count).ToArray(), physical.Skip(models.Count).ToArray());
        });
        return (prices, traced.Count + distinct.Length);
    }
}
