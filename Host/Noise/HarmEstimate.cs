using System.Text.Json.Nodes;

namespace QuantumRayTracing.Noise;

/// <summary>
/// How a gate-level exposure's graded harm was estimated, and how far it spreads: the mean over <paramref name="Traces"/> traces
/// of the run with <see cref="GateLevelExposure.TracedIterations"/> iterations, each grading a random share
/// <paramref name="Fraction"/> of its locations (1: all). One trace's per-iteration harm weight spreads about the mean with
/// standard deviation <paramref name="IterationSpread"/> (the measured outcomes of the uncomputation decide which corrections
/// a trace holds, and a sampled trace grades only some locations), so the mean's standard error is <see cref="IterationError"/>.
/// </summary>
public sealed record HarmEstimate(int Traces, double Fraction, double IterationSpread)
{
    /// <summary>The standard error of the mean per-iteration harm weight.</summary>
    public double IterationError => IterationSpread / Math.Sqrt(Traces);

    /// <summary>The estimate of <paramref name="values"/>, one trace's per-iteration harm weight each.</summary>
    public static HarmEstimate Of(IReadOnlyList<double> values, double fraction)
    {
        var mean = values.Average();
        var spread = values.Count > 1 ? Math.Sqrt(values.Sum(v => (v - mean) * (v - mean)) / (values.Count - 1)) : double.NaN;
        return new HarmEstimate(values.Count, fraction, spread);
    }

    public JsonObject ToJson() => new()
    {
        ["traces"] = Traces,
        ["fraction"] = Fraction,
        ["iterationSpread"] = double.IsNaN(IterationSpread) ? null : Math.Round(IterationSpread, 3),
    };

    public static HarmEstimate Parse(JsonNode node) =>
        new(node["traces"]!.GetValue<int>(), node["fraction"]!.GetValue<double>(), node["iterationSpread"]?.GetValue<double>() ?? double.NaN);
}
