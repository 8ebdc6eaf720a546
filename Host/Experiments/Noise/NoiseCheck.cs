using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Search;

using QuantumRayTracing.Noise;

namespace QuantumRayTracing.Experiments;

/// <summary>A circuit measured many times on the noisy simulator: the share of one outcome, beside what the approximation predicts.</summary>
public interface IModelCheckRow
{
    /// <summary>Runs measured.</summary>
    int Shots { get; }

    /// <summary>The outcome's observed share.</summary>
    double Observed { get; }

    /// <summary>The outcome's probability under the approximation with harmful share <paramref name="approximation"/>.</summary>
    double Predicted(DepolarizingApproximation approximation);
}

/// <summary>
/// The analytic model of a search and the wrong variants it is checked against (negative controls): the ideal formula
/// (no noise), every location harmful (s = 1), a third of them (s = 1/3), the model without the factor of the
/// preparation and measurement (Φ = F^r; on the lookup oracle its circuit evolved with a noiseless preparation and measurement),
/// the gate-level count without its grading (every Pauli the counting rule calls harmful a whole harm, the model before the harm
/// was graded), and a share s = 2/3 of the closed-form locations harmful (the lookup model before its circuit was evolved); and,
/// beside them, the graded harms taken as independent (Φ = F₀ · F^r, the gate-level model before its iterations were simulated
/// as channels on the index register).
/// </summary>
public enum SearchModel
{
    Counted,
    Ideal,
    ShareOne,
    ShareThird,
    ShareTwoThirds,
    WithoutPreparation,
    Ungraded,
    IndependentHarms,
}

/// <summary>One Grover run measured many times on the noisy simulator, beside what the depolarizing approximation predicts.</summary>
/// <param name="Oracle">"lookup" or "gate".</param>
/// <param name="Request">The run: N, the marked set, r, and for the gate oracle the ray's input.</param>
/// <param name="Noise">The noise it ran under.</param>
/// <param name="Locations">Noise locations of the whole run (preparation, r iterations, measurement).</param>
/// <param name="Shots">Runs measured.</param>
/// <param name="Hits">Runs that read a marked index.</param>
/// <param name="Exposure">The gate-level circuit's counted exposure; null for the lookup oracle.</param>
public sealed record NoiseCheckRow(string Oracle, GroverRequest Request, NoiseModel Noise, double Locations, int Shots, int Hits, GateLevelExposure? Exposure = null) : IModelCheckRow
{
    public int Count => Request.Marked.Count;

    public int Marked => Request.Marked.MarkedCount;

    public int Iterations => Request.Iterations;

    public double Observed => (double)Hits / Shots;

    /// <summary>P(marked) the approximation predicts with harmful share <paramref name="approximation"/> over every location.</summary>
    public double Predicted(DepolarizingApproximation approximation) =>
        DepolarizingApproximation.MarkedProbability(Count, Marked, Iterations, approximation.Fidelity(Noise, Locations));

    /// <summary>P(marked) by <paramref name="model"/>: the engines' model (the gate-level circuit's counted harm, the lookup circuit's evolution) or a wrong variant.</summary>
    public double Predicted(SearchModel model) => DepolarizingApproximation.MarkedProbability(Count, Marked, Iterations, model switch
    {
        SearchModel.Ideal => 1.0,
        SearchModel.ShareOne => new DepolarizingApproximation(1).Fidelity(Noise, Locations),
        SearchModel.ShareThird => new DepolarizingApproximation(1.0 / 3).Fidelity(Noise, Locations),
        SearchModel.ShareTwoThirds => DepolarizingApproximation.Default.Fidelity(Noise, Locations),
        SearchModel.Ungraded => Exposure is { } u ? (u.Outside.Ungraded + (double)Iterations * u.Iteration.Ungraded).Fidelity(Noise) : DepolarizingApproximation.Default.Fidelity(Noise, Locations),
        SearchModel.WithoutPreparation => Exposure is { } e ? Math.Min(1.0, Math.Pow(e.Iteration.Fidelity(Noise), Iterations))
            : LookupSearchModel.Evolves(Count) ? LookupSearchModel.Shared.RunFidelity(Noise, Count, Marked, Iterations, noisyOutside: false)
            : DepolarizingApproximation.Default.Fidelity(Noise, Locations - NoiseLocations.PrepareAndMeasure(Count)),
        SearchModel.IndependentHarms => Exposure is { } h ? h.IndependentHarmsFidelity(Noise, Iterations) : DepolarizingApproximation.Default.Fidelity(Noise, Locations),
        _ => Exposure is { } g ? g.RunFidelity(Noise, Count, Marked, Iterations) : DepolarizingApproximation.Default.RunFidelity(Noise, Request),
    });

    /// <summary>A lookup row's P(marked) with its circuit evolved on the row's own marked set, not the typical one the model takes; null elsewhere.</summary>
    public double? OwnSetProbability() => Exposure is null && LookupSearchModel.Evolves(Count) && Marked > 0
        ? LookupCircuitDensity.MarkedProbabilities(Request.Marked, Iterations, CircuitRates.Of(Noise))[Iterations]
        : null;

    /// <summary>P(marked) of the gate-level model with <paramref name="wholeHarm"/> for an error the grading cannot follow; the engines' model on a lookup row.</summary>
    public double PredictedWithWholeHarm(double wholeHarm) => Exposure is { } g
        ? DepolarizingApproximation.MarkedProbability(Count, Marked, Iterations, g.RunFidelity(Noise, Count, Marked, Iterations, wholeHarm))
        : Predicted(SearchModel.Counted);

    /// <summary>Binomial standard error of <see cref="Observed"/> at <paramref name="model"/>'s probability.</summary>
    public double StandardError(SearchModel model)
    {
        var p = Math.Clamp(Predicted(model), 1e-9, 1 - 1e-9);
        return Math.Sqrt(p * (1 - p) / Shots);
    }

    /// <summary>Whether the observed share lies within <paramref name="tolerance"/> + z·σ of <paramref name="model"/>.</summary>
    public bool Accepts(SearchModel model, double tolerance, double z) => Math.Abs(Observed - Predicted(model)) <= tolerance + z * StandardError(model);

    /// <summary>
    /// Whether <paramref name="model"/> differs from the engines' model on this row by more than both acceptance regions
    /// together, so that the check can tell them apart.
    /// </summary>
    public bool Separates(SearchModel model, double tolerance, double z) =>
        Math.Abs(Predicted(model) - Predicted(SearchModel.Counted)) > 2 * tolerance + z * (StandardError(model) + StandardError(SearchModel.Counted));

    /// <summary>Binomial standard error of <see cref="Observed"/> at the predicted probability.</summary>
    public double StandardError(DepolarizingApproximation approximation)
    {
        var p = Math.Clamp(Predicted(approximation), 1e-9, 1 - 1e-9);
        return Math.Sqrt(p * (1 - p) / Shots);
    }
}

/// <summary>
/// Measures Grover runs on the noisy full-state simulator (lookup oracle on <see cref="FullStateEngine"/>,
/// gate-level oracle on <see cref="GateEngine"/>) and compares P(marked) with the depolarizing approximation;
/// fits the harmful share per circuit shape where the default misses.
/// </summary>
public static class NoiseCheck
{
    /// <summary>Two-sided z bound at false-failure 1e-6 per comparison.</summary>
    public const double Z = 4.8916;

    /// <summary>
    /// The search model's acceptance: |observed − model| ≤ <see cref="SearchTolerance"/> + z·σ. A stated tolerance for what
    /// the global depolarizing form leaves out, far below the 0.06 of the supersampling circuits.
    /// </summary>
    public const double SearchTolerance = 0.02;

    /// <summary>
    /// Runs each request <paramref name="shots"/> times under each noise model and counts marked outcomes. Gate
    /// requests (with an oracle input) run on the gate engine, their locations from the circuit the bridge extracts.
    /// </summary>
    public static IReadOnlyList<NoiseCheckRow> Measure(BridgePool pool, IReadOnlyList<GroverRequest> requests, IReadOnlyList<NoiseModel> noises, int shots)
    {
        var rows = new List<NoiseCheckRow>();
        foreach (var noise in noises)
        {
            using var lookup = new FullStateEngine(pool, ownsPool: false, noise: noise);
            using var gate = new GateEngine(pool, ownsPool: false, noise: noise);
            foreach (var request in requests)
            {
                IGroverEngine engine = request.Oracle is null ? lookup : gate;
                var measured = engine.Measure(Enumerable.Repeat(request, shots).ToArray());
                var hits = measured.Count(i => i < request.Marked.Count && request.Marked.Contains(i));
                var exposure = request.Oracle is { } oracle ? Exposure(pool, oracle) : null;
                var locations = exposure?.Run(request.Iterations).Locations
                    ?? NoiseLocations.PrepareAndMeasure(request.Marked.Count) + (double)request.Iterations * NoiseLocations.LookupIteration(request.Marked);
                rows.Add(new NoiseCheckRow(request.Oracle is null ? "lookup" : "gate", request, noise, locations, shots, hits, exposure));
            }
        }
        return rows;
    }

    private static readonly Dictionary<string, GateLevelExposure> ExposureCache = [];

    /// <summary>The gate-level circuit's counted exposure for <paramref name="oracle"/>, traced once per circuit.</summary>
    public static GateLevelExposure Exposure(BridgePool pool, Intersection.OracleInput oracle)
    {
        var key = GateEngine.OracleArgument(oracle);
        lock (ExposureCache)
        {
            if (!ExposureCache.TryGetValue(key, out var exposure))
                ExposureCache[key] = exposure = GateLevelExposure.Trace(pool, oracle, $"N = {oracle.Table.Count}, {oracle.Table.CoordinateBits} coordinate bits");
            return exposure;
        }
    }

    /// <summary>
    /// The harm of an error the grading cannot follow, as a share of a whole harm, that best fits the gate-level
    /// <paramref name="rows"/> (least squares in units of each row's standard error, on a grid of step 0.01 over 0.2 … 1.5):
    /// the fit behind <see cref="SearchChannels.FittedWholeHarm"/>.
    /// </summary>
    public static double FitWholeHarm(IReadOnlyList<NoiseCheckRow> rows)
    {
        var (best, bestCost) = (1.0, double.PositiveInfinity);
        for (var k = 20; k <= 150; k++)
        {
            var cost = rows.Sum(r => SquaredError(r.Observed, r.PredictedWithWholeHarm(k / 100.0), r.Shots));
            if (cost < bestCost) (best, bestCost) = (k / 100.0, cost);
        }
        return best;
    }

    /// <summary>
    /// The harmful share that best fits the rows (least squares in units of each row's standard error, on a
    /// grid of step 0.005 over 0.05 … 1.5): the fitted effective F = (1 − p)^(s · L) of one circuit shape.
    /// </summary>
    public static double FitHarmfulShare(IReadOnlyList<IModelCheckRow> rows)
    {
        var (best, bestCost) = (DepolarizingApproximation.DefaultHarmfulShare, double.PositiveInfinity);
        for (var s = 0.05; s <= 1.5 + 1e-9; s += 0.005)
        {
            var approximation = new DepolarizingApproximation(s);
            var cost = rows.Sum(r => SquaredError(r.Observed, r.Predicted(approximation), r.Shots));
            if (cost < bestCost) (best, bestCost) = (s, cost);
        }
        return best;
    }

    /// <summary>A row's squared gap in units of its binomial variance at the prediction (kept off 0 and 1).</summary>
    private static double SquaredError(double observed, double predicted, int shots)
    {
        var p = Math.Clamp(predicted, 1e-3, 1 - 1e-3);
        var d = observed - p;
        return d * d * shots / (p * (1 - p));
    }
}
