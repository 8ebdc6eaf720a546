using System.Text.Json.Nodes;

namespace QuantumRayTracing.Noise;

/// <summary>
/// A gate-level run's iterations as channels on the index register (<see cref="IterationChannels"/>): every iteration but the
/// last (<see cref="Inner"/>) and the last (<see cref="Last"/>) differ. An X that leaves garbage on an oracle's work qubits
/// dephases the register in the last oracle section, where nothing reads those qubits again, and is a whole harm before
/// another oracle, which computes on them. From the traced run with r_t iterations: its first r_t − 1 oracle sections averaged,
/// and its last.
/// </summary>
/// <param name="Inner">An iteration followed by another; null where the traced run had one (then <paramref name="Last"/> stands in).</param>
/// <param name="Last">The last iteration, with the locations after its diffusion.</param>
public sealed record SearchChannels(IterationChannels? Inner, IterationChannels Last)
{
    /// <summary>
    /// The harm of an error whose effect the grading cannot follow (inside a diffusion, on a superposed qubit, garbage an
    /// oracle computes on), as a share of a whole harm: a fit, not a count. Least squares in units of the binomial standard
    /// error over the gate-level oracle's N = 8 runs (r = 1 and 2) at p = 6e-4 and 2e-3, 3200 shots each, rates the model
    /// check does not use (docs/noise.md, "The fitted share of a whole harm"; <c>qrt bench noise --shots 3200 --parts model</c>
    /// measures those runs again and refits on them).
    /// </summary>
    public const double FittedWholeHarm = 0.68;

    /// <summary>The traced run's channels from the bridge's <c>harmChannels</c>.</summary>
    public static SearchChannels FromTrace(JsonNode channels)
    {
        var sections = channels["dephasing"]!.AsArray().Count;
        if (sections == 0) throw new InvalidDataException("the traced run's channels hold no oracle section");
        var last = IterationChannels.FromSection(channels, sections - 1);
        if (sections == 1) return new SearchChannels(null, last);
        var inner = (1.0 / (sections - 1)) * Enumerable.Range(0, sections - 1).Select(s => IterationChannels.FromSection(channels, s)).Aggregate((a, b) => a + b);
        return new SearchChannels(inner, last);
    }

    /// <summary>Sums, for averaging traces; an inner part only where both have one.</summary>
    public static SearchChannels operator +(SearchChannels a, SearchChannels b) =>
        new(a.Inner is { } x && b.Inner is { } y ? x + y : null, a.Last + b.Last);

    public static SearchChannels operator *(double k, SearchChannels a) => new(a.Inner is { } inner ? k * inner : null, k * a.Last);

    /// <summary>
    /// P(marked) of a run with <paramref name="iterations"/> iterations over a <paramref name="register"/>-value register,
    /// <paramref name="marked"/> marked, under <paramref name="noise"/>, the preparation and measurement surviving with
    /// <paramref name="outside"/>, an error the grading cannot follow costing <paramref name="wholeHarm"/> of a whole harm.
    /// </summary>
    public double MarkedProbability(NoiseModel noise, int register, int marked, int iterations, double outside, double wholeHarm = FittedWholeHarm) =>
        DephasedSearch.MarkedProbability(register, marked, iterations, outside,
            (Inner ?? Last).Under(noise, wholeHarm), Last.Under(noise, wholeHarm));

    public JsonObject ToJson()
    {
        var json = new JsonObject { ["last"] = Last.ToJson() };
        if (Inner is { } inner) json["inner"] = inner.ToJson();
        return json;
    }

    public static SearchChannels Parse(JsonNode node, string shape) =>
        new(node["inner"] is { } inner ? IterationChannels.Parse(inner, shape, "inner") : null, IterationChannels.Parse(node["last"]!, shape, "last"));
}
