using System.Collections.Concurrent;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Noise;

/// <summary>
/// The lookup oracle's noisy Grover run as <see cref="LookupCircuitDensity"/> evolves it, kept per (noise, N, t): one evolution
/// gives P(marked) after every iteration count it has reached and continues when asked for more, so a render evolves each
/// marked count once, as deep as its searches go. Which indices are
/// marked changes the circuit only by its X toggles, so a run is evolved on a typical set of t indices, drawn once per (N, t)
/// with a fixed seed, not on each ray's own set (<see cref="TypicalSet"/>).
/// </summary>
public sealed class LookupSearchModel
{
    /// <summary>The model the analytic engine and the model check share.</summary>
    public static readonly LookupSearchModel Shared = new();

    private readonly ConcurrentDictionary<(CircuitRates Rates, int Count, int Marked, bool NoisyOutside), Lazy<LookupCircuitDensity.Evolution>> _evolutions = new();

    /// <summary>Evolutions kept at once.</summary>
    public const int MaxKept = 16;

    /// <summary>Whether runs over <paramref name="count"/> indices are evolved (<see cref="LookupCircuitDensity.Evolves"/>).</summary>
    public static bool Evolves(int count) => LookupCircuitDensity.Evolves(count);

    /// <summary>The t indices a run over N indices with t marked is evolved on: drawn without repeats, seeded by N and t.</summary>
    public static MarkedSet TypicalSet(int count, int marked)
    {
        ArgumentOutOfRangeException.ThrowIfGreaterThan(marked, count);
        var random = new SeededRandom((ulong)count << 32 | (uint)marked);
        var indices = Enumerable.Range(0, count).ToArray();
        for (var k = 0; k < marked; k++)
        {
            var j = k + random.NextInt(count - k);
            (indices[k], indices[j]) = (indices[j], indices[k]);
        }
        return new MarkedSet(count, indices[..marked]);
    }

    /// <summary>
    /// P(marked) of a run with <paramref name="iterations"/> iterations over <paramref name="count"/> indices, <paramref name="marked"/>
    /// of them marked, under <paramref name="noise"/>; with <paramref name="noisyOutside"/> false the preparation and measurement are noiseless.
    /// </summary>
    public double MarkedProbability(NoiseModel noise, int count, int marked, int iterations, bool noisyOutside = true) =>
        MarkedProbability(CircuitRates.Of(noise), count, marked, iterations, noisyOutside);

    /// <summary>The same under <paramref name="rates"/>: each gate's rate by its arity, and the readout error if they have one.</summary>
    public double MarkedProbability(CircuitRates rates, int count, int marked, int iterations, bool noisyOutside = true)
    {
        ArgumentNullException.ThrowIfNull(rates);
        if (marked == 0) return 0;
        var key = (rates, count, marked, noisyOutside);
        // Each evolution holds its matrix (8 MB at N = 64): past a bound they are let go, and a later question evolves again.
        if (!_evolutions.ContainsKey(key) && _evolutions.Count >= MaxKept) _evolutions.Clear();
        return _evolutions.GetOrAdd(key,
            static key => new(() => new LookupCircuitDensity.Evolution(TypicalSet(key.Count, key.Marked), key.Rates, key.NoisyOutside))).Value.MarkedProbability(iterations);
    }

    /// <summary>
    /// Φ of the run as the analytic engine samples it (ideal with Φ, else a uniform index): the share of the ideal run's excess
    /// over the uniform readout t/2^n the noisy run keeps, clamped to [0, 1]; 1 where the ideal run reads no better than uniform.
    /// </summary>
    public double RunFidelity(NoiseModel noise, int count, int marked, int iterations, bool noisyOutside = true) =>
        RunFidelity(CircuitRates.Of(noise), count, marked, iterations, noisyOutside);

    /// <summary>The same under <paramref name="rates"/>' gate noise; their readout error is left out, as the engine flips the bits it reads.</summary>
    public double RunFidelity(CircuitRates rates, int count, int marked, int iterations, bool noisyOutside = true)
    {
        ArgumentNullException.ThrowIfNull(rates);
        var gates = rates.GatesOnly;
        if (gates.IsNoiseless || marked == 0) return 1;
        return DepolarizingApproximation.FidelityOf(count, marked, iterations, () => MarkedProbability(gates, count, marked, iterations, noisyOutside)) is { } fidelity
            ? Math.Clamp(fidelity, 0, 1)
            : 1;
    }

    /// <summary>
    /// The run's harm-weighted locations to first order: −ln Φ / p at a per-gate rate small enough that Φ = exp(−p · H) holds,
    /// every Pauli at p/3 (beside a location count L, H / L is the share of errors that harm).
    /// </summary>
    public static double HarmWeight(int count, int marked, int iterations)
    {
        const double p = 1e-6;
        var noise = NoiseModel.Depolarizing(p);
        return -Math.Log(Shared.RunFidelity(noise, count, marked, iterations)) / p;
    }
}
