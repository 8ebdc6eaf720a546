using System.Globalization;
using System.Text.Json.Nodes;

namespace QuantumRayTracing.Noise;

/// <summary>
/// One Grover iteration's errors as two channels on the index register, as Quantum/noise-harm.mjs grades them: the errors
/// whose effect it cannot follow (<see cref="Full"/>, each a whole harm) leave the register uniformly mixed; the errors whose
/// effect is a known sign on some index branches, or garbage that stops some branches interfering, dephase it. A sign flip
/// multiplies the coherence of two branches it separates by −1, so at rate q the coherence decays by 1 − 2q; averaged over
/// the pairs of a class (a marked and an unmarked index, two unmarked, two marked) and summed over locations, each class's
/// coherence decays with its own weight. Unlike harms taken as independent, two sign flips on the same branches cancel,
/// and a register dephased in the last oracle section still reads the marked index it had concentrated there.
/// </summary>
/// <param name="Full">Errors graded a whole harm per iteration.</param>
/// <param name="Cross">Decay weight of a marked and an unmarked branch's coherence per iteration.</param>
/// <param name="Unmarked">The same for two unmarked branches.</param>
/// <param name="Marked">The same for two marked branches; null where the traced ray marked one index, and then taken as <paramref name="Unmarked"/>.</param>
public sealed record IterationChannels(PauliWeights Full, PauliWeights Cross, PauliWeights Unmarked, PauliWeights? Marked)
{
    /// <summary>
    /// The survival of each channel under <paramref name="noise"/>: uniform mixing at <paramref name="wholeHarm"/> of a harm per
    /// whole-harm error (<see cref="SearchChannels.FittedWholeHarm"/>), then each class's coherence.
    /// </summary>
    public DephasedSearch.Iteration Under(NoiseModel noise, double wholeHarm) => new(
        Math.Exp(wholeHarm * Full.LogSurvival(noise)), Math.Exp(Cross.LogSurvival(noise)), Math.Exp(Unmarked.LogSurvival(noise)), Math.Exp((Marked ?? Unmarked).LogSurvival(noise)));

    public static IterationChannels operator +(IterationChannels a, IterationChannels b) =>
        new(a.Full + b.Full, a.Cross + b.Cross, a.Unmarked + b.Unmarked, a.Marked is { } m && b.Marked is { } n ? m + n : null);

    public static IterationChannels operator *(double k, IterationChannels a) =>
        new(k * a.Full, k * a.Cross, k * a.Unmarked, a.Marked is { } m ? k * m : null);

    /// <summary>One oracle section's channels from the bridge's <c>harmChannels</c> (whole harm and dephasing are listed per section).</summary>
    public static IterationChannels FromSection(JsonNode channels, int section)
    {
        var dephasing = channels["dephasing"]![section]!;
        PauliWeights Class(string cls) => new(dephasing["X"]![cls]!.GetValue<double>(), dephasing["Y"]![cls]!.GetValue<double>(), dephasing["Z"]![cls]!.GetValue<double>());
        var marked = channels["marked"]!.GetValue<int>();
        return new IterationChannels(PauliWeights.Parse(channels["fullHarm"]![section]!), Class("cross"), Class("unmarked"), marked >= 2 ? Class("marked") : null);
    }

    public JsonObject ToJson()
    {
        var json = new JsonObject { ["full"] = Full.ToJson(), ["cross"] = Cross.ToJson(), ["unmarked"] = Unmarked.ToJson() };
        if (Marked is { } marked) json["marked"] = marked.ToJson();
        return json;
    }

    /// <summary>A table entry's channels; negative weights are refused (a decay, never a gain).</summary>
    public static IterationChannels Parse(JsonNode node, string shape, string part)
    {
        var channels = new IterationChannels(PauliWeights.Parse(node["full"]!), PauliWeights.Parse(node["cross"]!), PauliWeights.Parse(node["unmarked"]!),
            node["marked"] is { } marked ? PauliWeights.Parse(marked) : null);
        foreach (var (name, weights) in new[] { ("full", channels.Full), ("cross", channels.Cross), ("unmarked", channels.Unmarked), ("marked", channels.Marked ?? PauliWeights.None) })
            foreach (var (pauli, w) in new[] { ("X", weights.X), ("Y", weights.Y), ("Z", weights.Z) })
                if (!(w >= 0)) throw new InvalidDataException($"gate-level exposure of {shape}: channels.{part}.{name}.{pauli} is {w.ToString(CultureInfo.InvariantCulture)}, and a decay weight cannot be negative");
        return channels;
    }
}
