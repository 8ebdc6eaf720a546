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

/// <summary>One Grover run measured many times on the noisy simulator, beside what the depolarizing approximation predicts.</summary>
/// <param name="Oracle">"lookup" or "gate".</param>
/// <param name="Request">The run: N, the marked set, r, and for the gate oracle the ray's input.</param>
/// <param name="Noise">The noise it ran under.</param>
/// <param name="Locations">Noise locations of the whole run (preparation, r iterations, measurement).</param>
/// <param name="Shots">Runs measured.</param>
/// <param name="Hits">Runs that read a marked index.</param>
public sealed record NoiseCheckRow(string Oracle, GroverRequest Request, NoiseModel Noise, double Locations, int Shots, int Hits) : IModelCheckRow
{
    public int Count => Request.Marked.Count;

    public int Marked => Request.Marked.MarkedCount;

    public int Iterations => Request.Iterations;

    public double Observed => (double)Hits / Shots;

    /// <summary>P(marked) the approximation predicts with harmful share <paramref name="approximation"/>.</summary>
    public double Predicted(DepolarizingApproximation approximation) =>
        DepolarizingApproximation.MarkedProbability(Count, Marked, Iterations, approximation.Fidelity(Noise, Locations));

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
                rows.Add(new NoiseCheckRow(request.Oracle is null ? "lookup" : "gate", request, noise, Locations(pool, request), shots, hits));
            }
        }
        return rows;
    }

    private static readonly Dictionary<string, double> GateIterationCache = [];

    /// <summary>
    /// Noise locations of a whole run: closed form for the lookup oracle; for the gate-level oracle the
    /// bridge's summary of one iteration on fresh registers, cached per circuit (its Z and CZ counts vary
    /// slightly with the measurement-based uncomputation's outcomes; the first trace is kept).
    /// </summary>
    public static double Locations(BridgePool pool, GroverRequest request)
    {
        var outside = NoiseLocations.PrepareAndMeasure(request.Marked.Count);
        if (request.Oracle is not { } oracle) return outside + (double)request.Iterations * NoiseLocations.LookupIteration(request.Marked);
        var expression = $"{QSharpOperations.ApplyGateGroverIterationOnNewRegisters}({GateEngine.OracleArgument(oracle)})";
        double perIteration;
        lock (GateIterationCache)
        {
            if (!GateIterationCache.TryGetValue(expression, out perIteration))
            {
                var traced = 0.0;
                pool.ForEach([expression], (e, bridge) => traced = NoiseLocations.FromCircuit(bridge.Circuit(e)["native"]!.AsObject()));
                GateIterationCache[expression] = perIteration = traced;
            }
        }
        return outside + request.Iterations * perIteration;
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
            var cost = rows.Sum(r =>
            {
                var p = Math.Clamp(r.Predicted(approximation), 1e-3, 1 - 1e-3);
                var d = r.Observed - p;
                return d * d * r.Shots / (p * (1 - p));
            });
            if (cost < bestCost) (best, bestCost) = (s, cost);
        }
        return best;
    }
}
