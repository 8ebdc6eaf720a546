using QuantumRayTracing.Engines;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Noise;

/// <summary>
/// The global depolarizing approximation of a noisy Grover run: with probability Φ the run is the ideal
/// one, otherwise the index register is left maximally mixed and reads uniformly over its 2^n values.
/// So P(marked) = Φ · sin²((2r+1)θ) + (1 − Φ) · t / 2^n (t / N when N is a power of two). On the lookup oracle
/// Φ is read from its circuit evolved exactly as a density matrix (<see cref="LookupSearchModel"/>) where N is a power of two up
/// to 64; elsewhere Φ = F₀ · F^r, F = (1 − p)^(s · L) per iteration of L noise locations, F₀ the same for the preparation
/// and measurement, and s the share of Pauli errors that harm the run. On the gate-level oracle Φ is what its
/// iterations' channels on the index register keep (<see cref="GateLevelExposure.RunFidelity(NoiseModel, int, int, int)"/>).
/// </summary>
/// <param name="HarmfulShare">
/// s of the closed-form locations where no circuit is evolved (the lookup oracle past N = 64 or at N not a power of two, the
/// supersampling circuits): by default 2/3, as a Z error on a qubit in a basis state does nothing.
/// </param>
/// <param name="GateLevel">
/// The gate-level oracle's exposure, counted location by location from its circuit (<see cref="NoiseExposure"/>);
/// when given, a run's Φ comes from it and <paramref name="HarmfulShare"/> plays no part. Null: the lookup oracle.
/// </param>
public sealed record DepolarizingApproximation(double HarmfulShare = DepolarizingApproximation.DefaultHarmfulShare, GateLevelExposure? GateLevel = null)
{
    public const double DefaultHarmfulShare = 2.0 / 3.0;

    public static readonly DepolarizingApproximation Default = new();

    /// <summary>Probability that <paramref name="locations"/> noise locations leave the run unharmed.</summary>
    public double Fidelity(NoiseModel noise, double locations) =>
        noise.PerGate <= 0 ? 1.0 : Math.Exp(HarmfulShare * locations * Math.Log(1 - Math.Min(noise.PerGate, 1 - 1e-12)));

    /// <summary>The oracle whose circuit Φ counts.</summary>
    public NoiseOracle Oracle => GateLevel is null ? NoiseOracle.Lookup : NoiseOracle.GateLevel;

    /// <summary>
    /// Φ of a Grover run: the gate-level circuit's counted exposure; the lookup circuit's evolution; or past what is evolved, the
    /// lookup oracle's locations (<see cref="NoiseLocations"/>) at share s.
    /// </summary>
    public double RunFidelity(NoiseModel noise, GroverRequest request) =>
        RunFidelity(noise, request.Marked.Count, request.Marked.MarkedCount, request.Iterations, request.Marked);

    // Φ by oracle: the gate-level circuit's, the evolved lookup circuit's, or the lookup oracle's counted locations over
    // `set` (null: the first t indices, counted once per N and t).
    private double RunFidelity(NoiseModel noise, int count, int marked, int iterations, MarkedSet? set) =>
        GateLevel is { } gate ? gate.RunFidelity(noise, count, marked, iterations)
        : LookupSearchModel.Evolves(count) ? LookupSearchModel.Shared.RunFidelity(noise, count, marked, iterations)
        : Fidelity(noise, NoiseLocations.PrepareAndMeasure(count) + (double)iterations * (set is null
            ? _lookupIterations.GetOrAdd((count, marked), static k => NoiseLocations.LookupIteration(new MarkedSet(k.Count, Enumerable.Range(0, k.Marked).ToArray())))
            : NoiseLocations.LookupIteration(set)));

    /// <summary>
    /// Φ of a Grover run under <paramref name="rates"/>' gate noise, each gate at its arity's rate (a device model; their readout
    /// error is the engine's to apply to the index it reads): the gate-level circuit's exposure by gate kind, the lookup circuit's
    /// evolution, or its counted locations by arity at share s. Rates that are one <see cref="NoiseModel"/> give that model's Φ.
    /// </summary>
    public double RunFidelity(CircuitRates rates, GroverRequest request) =>
        RunFidelity(rates, request.Marked.Count, request.Marked.MarkedCount, request.Iterations, request.Marked);

    private double RunFidelity(CircuitRates rates, int count, int marked, int iterations, MarkedSet? set)
    {
        var gates = rates.GatesOnly;
        if (gates.Uniform is { } noise) return RunFidelity(noise, count, marked, iterations, set);
        if (GateLevel is { } gate) return gate.RunFidelity(gates, count, marked, iterations);
        if (LookupSearchModel.Evolves(count)) return LookupSearchModel.Shared.RunFidelity(gates, count, marked, iterations);
        set ??= new MarkedSet(count, Enumerable.Range(0, marked));
        var multiQubit = (double)iterations * NoiseLocations.LookupIterationMultiQubit(set);
        var oneQubit = SearchRegisters.For(count).IndexQubits + (double)iterations * NoiseLocations.LookupIteration(set) - multiQubit;
        return Fidelity(gates.OneQubit, oneQubit) * Fidelity(gates.TwoQubit, multiQubit) * Fidelity(gates.Measurement, SearchRegisters.For(count).IndexQubits);
    }

    /// <summary>P(marked) of a run with fidelity Φ: the ideal share weighted by Φ, the uniform share by 1 − Φ.</summary>
    public static double MarkedProbability(int count, int marked, int iterations, double fidelity)
    {
        var readable = 1 << SearchRegisters.For(count).IndexQubits;
        return fidelity * GroverProbability.OfMarked(count, marked, iterations) + (1 - fidelity) * marked / readable;
    }

    /// <summary>
    /// Φ that <see cref="MarkedProbability(int, int, int, double)"/> turns into the noisy run's P(marked) (<paramref name="noisy"/>,
    /// asked only when needed): the share of the ideal run's excess over the uniform readout t/2^n the noisy run keeps, unclamped;
    /// null where the ideal run reads no better than uniform, so that no Φ is defined.
    /// </summary>
    public static double? FidelityOf(int count, int marked, int iterations, Func<double> noisy)
    {
        ArgumentNullException.ThrowIfNull(noisy);
        var uniform = (double)marked / (1 << SearchRegisters.For(count).IndexQubits);
        var ideal = GroverProbability.OfMarked(count, marked, iterations);
        return Math.Abs(ideal - uniform) < 1e-9 ? null : (noisy() - uniform) / (ideal - uniform);
    }

    /// <summary>P(marked) of a Grover run under <paramref name="noise"/>.</summary>
    public double MarkedProbability(NoiseModel noise, GroverRequest request) =>
        MarkedProbability(request.Marked.Count, request.Marked.MarkedCount, request.Iterations, RunFidelity(noise, request));

    private readonly System.Collections.Concurrent.ConcurrentDictionary<(int Count, int Marked), long> _lookupIterations = new();

    /// <summary>
    /// P(marked) of a run under <paramref name="noise"/> for the passes' miss rates: the gate-level circuit's Φ depends on r
    /// alone; the lookup oracle's on the marked set too, taken as its typical set (evolved) or the first t indices (counted).
    /// </summary>
    public FalseNegativeRate.RunSuccess NoisySuccess(NoiseModel noise) => (count, marked, iterations) =>
        MarkedProbability(count, marked, iterations, RunFidelity(noise, count, marked, iterations, set: null));

    /// <summary>
    /// <see cref="NoisySuccess(NoiseModel)"/> under <paramref name="rates"/>: Φ from their gate noise, and each read index's bits
    /// flipped by their readout error (<see cref="MarkedReadout"/>, on the typical marked set).
    /// </summary>
    public FalseNegativeRate.RunSuccess NoisySuccess(CircuitRates rates)
    {
        ArgumentNullException.ThrowIfNull(rates);
        if (rates.Uniform is { } noise) return NoisySuccess(noise);
        return (count, marked, iterations) =>
        {
            var fidelity = RunFidelity(rates, count, marked, iterations, set: null);
            if (!rates.HasReadoutError) return MarkedProbability(count, marked, iterations, fidelity);
            var readout = _readouts.GetOrAdd((rates, count, marked), static k => MarkedReadout.Of(k.Rates, LookupSearchModel.TypicalSet(k.Count, k.Marked)));
            return readout.Read(GroverProbability.OfMarked(count, marked, iterations), fidelity);
        };
    }

    private readonly System.Collections.Concurrent.ConcurrentDictionary<(CircuitRates Rates, int Count, int Marked), MarkedReadout> _readouts = new();

    /// <summary>How the model is named beside every result it produces under a device model.</summary>
    public string Description(DeviceNoiseModel device)
    {
        ArgumentNullException.ThrowIfNull(device);
        var readout = device.HasReadoutError ? "; the readout error flips each bit of every index the engine samples, with its seeded generator" : "";
        return GateLevel is { } gate
            ? $"{device.Description()}, global depolarizing approximation over the {NoiseOracle.GateLevel.Description()}, its harm traced once per oracle shape (here on {gate.Shape}):"
                + " each gate kind at its arity's rate, its harm counted per noise location"
                + (gate.Channels is null ? "" : $", the iterations simulated as channels on the index register with each gate kind weighed by its harm (an approximation; whole-harm share {SearchChannels.FittedWholeHarm:0.00}, fitted)")
                + readout
            : $"{device.Description()}, over the {NoiseOracle.Lookup.Description()}: its circuit evolved exactly as a density matrix with each gate at its arity's rate, on a typical marked set per N and t, read as Φ of the depolarizing form;"
                + $" N above 64 or not a power of two: harmful share {HarmfulShare:0.###} of counted locations at their arity's rate" + readout;
    }

    /// <summary>How the model is named beside every result it produces.</summary>
    public string Description(NoiseModel noise) =>
        noise.IsNoiseless ? noise.Description()
        : GateLevel is { } gate
            ? $"{noise.Description()}, global depolarizing approximation over the {NoiseOracle.GateLevel.Description()}, its harm traced once per oracle shape (here on {gate.Shape}): harm counted per noise location"
                + (gate.Channels is null ? "" : $", the iterations simulated as channels on the index register (whole-harm share {SearchChannels.FittedWholeHarm:0.00}, fitted)")
            : $"{noise.Description()}, over the {NoiseOracle.Lookup.Description()}: its circuit (index register and ladder auxiliaries) evolved exactly as a density matrix"
                + $" under the Pauli channel of every gate, on a typical marked set per N and t, read as Φ of the depolarizing form; N above 64 or not a power of two: harmful share {HarmfulShare:0.###} of counted locations";
}
