using System.Text.Json.Nodes;

namespace QuantumRayTracing.Noise;

/// <summary>
/// How a gate-level exposure's graded harm was estimated, and how far it spreads: the mean over several traces of the run with
/// <paramref name="Iterations"/> iterations, each grading a random share <paramref name="Fraction"/> of its locations (1: all),
/// whose per-iteration harm weights were <paramref name="IterationTraces"/>. They differ because the measured outcomes of the
/// uncomputation decide which corrections a trace holds, and a sampled trace grades only some locations.
/// </summary>
public sealed record HarmEstimate(int Iterations, IReadOnlyList<double> IterationTraces, double Fraction)
{
    /// <summary>Traces averaged.</summary>
    public int Traces => IterationTraces.Count;

    /// <summary>The standard deviation of one trace's per-iteration harm weight about their mean (NaN for one trace).</summary>
    public double IterationSpread
    {
        get
        {
            if (Traces < 2) return double.NaN;
            var mean = IterationTraces.Average();
            return Math.Sqrt(IterationTraces.Sum(v => (v - mean) * (v - mean)) / (Traces - 1));
        }
    }

    /// <summary>The standard error of the mean per-iteration harm weight.</summary>
    public double IterationError => IterationSpread / Math.Sqrt(Traces);

    public JsonObject ToJson() => new()
    {
        ["tracedIterations"] = Iterations,
        ["fraction"] = Fraction,
        ["iterationTraces"] = new JsonArray([.. IterationTraces.Select(v => (JsonNode?)Math.Round(v, 3))]),
    };

    public static HarmEstimate Parse(JsonNode node) =>
        new(node["tracedIterations"]!.GetValue<int>(), node["iterationTraces"]!.AsArray().Select(v => v!.GetValue<double>()).ToArray(), node["fraction"]!.GetValue<double>());
}
