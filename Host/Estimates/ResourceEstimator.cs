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
        pool.ForEach(Enumerable.Range(0, jobs.Count).ToArray(), (k, bridge) =>
        {
            var (circuit, subject) = jobs[k];
            var (logical, physical) = Measure(bridge, circuit.Expression(subject));
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

    /// <summary>
    /// The physical figures of circuits known only by their logical counts, on every model, in order:
    /// the estimator prices the counts themselves (<c>AccountForLogicalCounts</c>), which gives what it
    /// gives the traced circuit with those counts.
    /// </summary>
    public IReadOnlyList<IReadOnlyList<PhysicalEstimate>> EstimateCounts(IReadOnlyList<LogicalCounts> counts, Action? onDone = null)
    {
        var results = new IReadOnlyList<PhysicalEstimate>[counts.Count];
        pool.ForEach(Enumerable.Range(0, counts.Count).ToArray(), (k, bridge) =>
        {
            var (logical, physical) = Measure(bridge, counts[k].AccountingExpression);
            if (logical with { Ccix = counts[k].Ccix } != counts[k])
                throw new BridgeException($"the estimator counted {logical} for the counts {counts[k]}");
            results[k] = physical;
            onDone?.Invoke();
        });
        return results;
    }

    private (LogicalCounts Logical, PhysicalEstimate[] Physical) Measure(QSharpBridge bridge, string expression)
    {
        var parameters = new JsonArray(models.Select(m => (JsonNode)m.Parameters()).ToArray());
        var estimates = bridge.Estimate(expression, parameters);
        if (estimates.Count != models.Count)
            throw new BridgeException($"the estimator returned {estimates.Count} results for {models.Count} qubit models");
        return (LogicalCounts.Parse(estimates[0]!), models.Select((m, i) => PhysicalEstimate.Parse(m, estimates[i]!)).ToArray());
    }
}
