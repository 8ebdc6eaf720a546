using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// Measures circuits through the Q# bridges: the Resource Estimator (logical counts, and physical
/// figures for every qubit model in one call) and, when asked, the QDK's circuit extraction (gates by
/// kind and depth). Jobs run on every bridge of the pool at once.
/// </summary>
/// <remarks>
/// The QDK's circuit extraction slows down more than linearly with a circuit's length (measured at
/// N = 512: a QSearch run with r = 2 in 5 s, with r = 6 in 34 s, while simulating it takes 2 s and
/// 4 s), so a circuit that repeats a body more than <see cref="TracedRepeats"/> times is traced with
/// the body once and twice and extrapolated.
/// </remarks>
public sealed class ResourceEstimator(BridgePool pool, IReadOnlyList<QubitModel> models, bool withCircuits)
{
    /// <summary>Repetitions up to which a repeating circuit is traced whole.</summary>
    public const int TracedRepeats = 2;

    public IReadOnlyList<QubitModel> Models => models;

    public bool WithCircuits => withCircuits;

    /// <summary>One estimate per (circuit, subject), in order.</summary>
    public IReadOnlyList<CircuitEstimate> Estimate(IReadOnlyList<(EstimatedCircuit Circuit, EstimateSubject Subject)> jobs, Action? onDone = null)
    {
        var results = new CircuitEstimate[jobs.Count];
        var parameters = new JsonArray(models.Select(m => (JsonNode)m.Parameters()).ToArray());
        pool.ForEach(Enumerable.Range(0, jobs.Count).ToArray(), (k, bridge) =>
        {
            var (circuit, subject) = jobs[k];
            var expression = circuit.Expression(subject);
            var estimates = bridge.Estimate(expression, (JsonArray)parameters.DeepClone());
            if (estimates.Count != models.Count)
                throw new BridgeException($"the estimator returned {estimates.Count} results for {models.Count} qubit models");
            var logical = LogicalCounts.Parse(estimates[0]!);
            var physical = models.Select((m, i) => PhysicalEstimate.Parse(m, estimates[i]!)).ToArray();
            CircuitCounts Trace(EstimateSubject s) => CircuitCounts.Parse(bridge.Circuit(circuit.Expression(s)));
            var counts = !withCircuits ? null
                : circuit.RepeatsIterations && subject.Iterations > TracedRepeats
                    ? CircuitCounts.Extrapolate(Trace(subject with { Iterations = 1 }), Trace(subject with { Iterations = 2 }), subject.Iterations)
                    : Trace(subject);
            results[k] = new CircuitEstimate(circuit, subject, logical, physical, counts, circuit.Registers(subject));
            onDone?.Invoke();
        });
        return results;
    }
}
