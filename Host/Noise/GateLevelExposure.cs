using System.Globalization;
using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Noise;

/// <summary>
/// The noise exposure of a QSearch run on the gate-level oracle (<c>MeasureGateGroverSearch</c>, the circuit
/// <c>qrt estimate</c> prices): the preparation and measurement (<see cref="Outside"/>) and one Grover iteration
/// (<see cref="Iteration"/>). Locations from the circuits the QDK extracts with no iteration and with
/// <see cref="TracedIterations"/> (their difference per iteration, as for the estimates; Z and CZ counts vary slightly with the
/// measurement-based uncomputation's outcomes). The graded harm (<see cref="Estimate"/> says how) is split by location, not by
/// a difference of traces: the preparation's H and the final measurement are <see cref="Outside"/>, the rest of the traced run
/// shared equally by its iterations, so neither part can go negative.
/// </summary>
/// <param name="Shape">What the circuit was traced for: N, coordinate bits and the ray, in words.</param>
/// <param name="Outside">The preparation and the index measurement.</param>
/// <param name="Iteration">One Grover iteration: the phase oracle and the reflection.</param>
/// <param name="Estimate">How the graded harm was estimated and its spread; null when it is not graded.</param>
/// <param name="Channels">
/// The iterations' errors as channels on the index register (<see cref="SearchChannels"/>), the run's Φ simulated with them;
/// null: Φ = F₀ · F^r, the graded harms taken as independent.
/// </param>
public sealed record GateLevelExposure(string Shape, NoiseExposure Outside, NoiseExposure Iteration, HarmEstimate? Estimate = null, SearchChannels? Channels = null)
{
    /// <summary>The most iterations of a traced run whose graded harm the table holds.</summary>
    public const int MaxTracedIterations = 2;

    /// <summary>
    /// Iterations of the run traced for <paramref name="input"/>: <see cref="MaxTracedIterations"/>, or fewer where the ray's
    /// optimal count is lower. A run past its optimum can read no better than uniform (N = 4, t = 1, r = 2: P(marked) = 1/4), and
    /// there the grading's h = (P₀ − P_e) / (P₀ − t/2^n) has nothing to divide by and counts every error whole.
    /// </summary>
    public static int TracedIterations(OracleInput input)
    {
        ArgumentNullException.ThrowIfNull(input);
        return Math.Clamp(GroverProbability.OptimalIterations(input.Table.Count, input.Table.Marked(input.Window).MarkedCount), 1, MaxTracedIterations);
    }

    /// <summary>The exposure of a run with <paramref name="iterations"/> Grover iterations.</summary>
    public NoiseExposure Run(int iterations) => Outside + (double)iterations * Iteration;

    private readonly System.Collections.Concurrent.ConcurrentDictionary<(NoiseModel Outside, NoiseModel Iteration), (double Outside, double Iteration)> _logFidelities = new();

    private readonly System.Collections.Concurrent.ConcurrentDictionary<(NoiseModel Outside, NoiseModel Iteration, int Count, int Marked, int Iterations), double> _channelFidelities = new();

    /// <summary>Φ = F₀ · F^r of a run with <paramref name="iterations"/> iterations, the graded harms taken as independent.</summary>
    public double IndependentHarmsFidelity(NoiseModel noise, int iterations) => IndependentHarmsFidelity(noise, noise, iterations);

    // The preparation and measurement under one model, the iterations under another: a device model's rates, each part's own mix of gates.
    private double IndependentHarmsFidelity(NoiseModel outside, NoiseModel iteration, int iterations)
    {
        var logs = _logFidelities.GetOrAdd((outside, iteration), n => (Math.Log(Outside.Fidelity(n.Outside)), Math.Log(Iteration.Fidelity(n.Iteration))));
        return Math.Exp(logs.Outside + iterations * logs.Iteration);
    }

    /// <summary>
    /// Φ of a run with <paramref name="iterations"/> iterations over <paramref name="count"/> values, <paramref name="marked"/>
    /// of them marked: with <see cref="Channels"/>, the share of the ideal run's excess over the uniform readout that the
    /// simulated channels keep, (P − u) / (P₀ − u), clamped to [0, 1] (a run past its optimum, P₀ below u, can be dephased
    /// beyond u); otherwise <see cref="IndependentHarmsFidelity(NoiseModel, int)"/>. F₀ (<see cref="Outside"/>) stays a whole-harm factor.
    /// </summary>
    public double RunFidelity(NoiseModel noise, int count, int marked, int iterations) => RunFidelity(noise, noise, count, marked, iterations);

    /// <summary>
    /// The same under <paramref name="rates"/>' gate noise (their readout is not the circuit's): the preparation and measurement
    /// and the iterations each under the model that leaves their graded harm as the rates leave it (<see cref="NoiseExposure.Effective"/>):
    /// exact for the harms taken as independent; for the channels, an approximation that weighs each channel's gate kinds by
    /// their harm.
    /// </summary>
    public double RunFidelity(CircuitRates rates, int count, int marked, int iterations)
    {
        ArgumentNullException.ThrowIfNull(rates);
        var gates = rates.GatesOnly;
        if (gates.Uniform is { } noise) return RunFidelity(noise, count, marked, iterations);
        var (outside, iteration) = _effective.GetOrAdd(gates, static (g, self) => (self.Outside.Effective(g), self.Iteration.Effective(g)), this);
        return RunFidelity(outside, iteration, count, marked, iterations);
    }

    private readonly System.Collections.Concurrent.ConcurrentDictionary<CircuitRates, (NoiseModel Outside, NoiseModel Iteration)> _effective = new();

    private double RunFidelity(NoiseModel outside, NoiseModel iteration, int count, int marked, int iterations) =>
        Channels is null || iteration.PerGate <= 0 ? IndependentHarmsFidelity(outside, iteration, iterations)
        : _channelFidelities.GetOrAdd((outside, iteration, count, marked, iterations),
            static (key, self) => self.ChannelFidelity(key.Outside, key.Iteration, key.Count, key.Marked, key.Iterations, SearchChannels.FittedWholeHarm), this);

    /// <summary>The same with <paramref name="wholeHarm"/> for the harm of an error the grading cannot follow (the fit tries several), not kept.</summary>
    public double RunFidelity(NoiseModel noise, int count, int marked, int iterations, double wholeHarm) =>
        ChannelFidelity(noise, noise, count, marked, iterations, wholeHarm);

    private double ChannelFidelity(NoiseModel outside, NoiseModel iteration, int count, int marked, int iterations, double wholeHarm)
    {
        if (Channels is not { } channels || iteration.PerGate <= 0) return IndependentHarmsFidelity(outside, iteration, iterations);
        var register = 1 << Search.SearchRegisters.For(count).IndexQubits;
        return DepolarizingApproximation.FidelityOf(register, marked, iterations,
                () => channels.MarkedProbability(iteration, register, marked, iterations, Outside.Fidelity(outside), wholeHarm)) is { } fidelity
            ? Math.Clamp(fidelity, 0, 1)
            : IndependentHarmsFidelity(outside, iteration, iterations);
    }

    /// <summary>
    /// Traces <paramref name="input"/>'s search on <paramref name="pool"/>'s bridges with no iteration and, <paramref name="traces"/>
    /// times, with <see cref="TracedIterations"/> for it, grading each of the latter.
    /// </summary>
    /// <remarks>
    /// A trace's graded harm depends on its measured outcomes (which corrections it holds) and, when sampled, on which locations
    /// it grades, so the traces are averaged and their spread kept (<see cref="HarmEstimate"/>). Each grades its outside locations
    /// whole and the others with probability <paramref name="fraction"/> (seeded by the trace's number, weighted by the inverse),
    /// an unbiased estimate of the whole grading at a share of its time, which grows as the circuit's square.
    /// </remarks>
    /// <param name="pool">The bridges that trace the circuits.</param>
    /// <param name="input">The ray's oracle input; its marked set grades the harm.</param>
    /// <param name="shape">What the circuit was traced for, in words.</param>
    /// <param name="traces">Graded traces averaged (at least 2, for the spread).</param>
    /// <param name="fraction">Share of each trace's locations graded, in (0, 1].</param>
    public static GateLevelExposure Trace(BridgePool pool, OracleInput input, string shape, int traces = DefaultTraces, double fraction = 1)
    {
        ArgumentNullException.ThrowIfNull(pool);
        ArgumentNullException.ThrowIfNull(input);
        ArgumentOutOfRangeException.ThrowIfLessThan(traces, 2);
        if (!(fraction > 0 && fraction <= 1)) throw new ArgumentOutOfRangeException(nameof(fraction), fraction, "the graded share must lie in (0, 1]");
        var argument = GateEngine.OracleArgument(input);
        var traced = TracedIterations(input);
        var marked = input.Table.Marked(input.Window).Indices.ToArray();
        string Expression(int r) => $"{QSharpOperations.MeasureGateGroverSearch}({argument}, {r.ToString(CultureInfo.InvariantCulture)})";
        NoiseExposure outsideCounts = null!;
        var graded = new (NoiseExposure Run, NoiseExposure Outside, SearchChannels Channels)[traces];
        pool.ForEach(Enumerable.Range(-1, traces + 1).ToArray(), (copy, bridge) =>
        {
            if (copy < 0)
            {
                outsideCounts = NoiseExposure.Parse(bridge.Circuit(Expression(0), timeout: TimeSpan.FromMinutes(30), exposure: true)["exposure"]!);
                return;
            }
            var summary = bridge.Circuit(Expression(traced), timeout: TimeSpan.FromMinutes(60), exposure: true, marked: marked,
                sampling: fraction < 1 ? (fraction, (uint)copy + 1) : null);
            if (summary["harm"] is not { } harm || summary["outsideHarm"] is not { } outside || summary["harmChannels"] is not { } channels)
                throw new InvalidOperationException($"the grading did not read {shape}'s traced circuit as a Grover search over its index register");
            graded[copy] = (NoiseExposure.Parse(summary["exposure"]!, harm), NoiseExposure.Parse(summary["exposure"]!, outside), SearchChannels.FromTrace(channels));
        });
        // Per trace: the outside locations' harm, and the rest shared by the iterations (counts: the run's less the r = 0 circuit's).
        var iterations = graded.Select(g => (1.0 / traced) * (g.Run - (outsideCounts with { Harm = g.Outside.Harm }))).ToArray();
        var mean = (1.0 / traces) * iterations.Aggregate((a, b) => a + b);
        var outsideHarm = (1.0 / traces) * graded.Select(g => outsideCounts with { Harm = g.Outside.Harm }).Aggregate((a, b) => a + b);
        var channelMean = (1.0 / traces) * graded.Select(g => g.Channels).Aggregate((a, b) => a + b);
        return new GateLevelExposure(shape, outsideHarm, mean, new HarmEstimate(traced, iterations.Select(i => i.HarmWeight).ToArray(), fraction), channelMean);
    }

    /// <summary>Graded traces averaged per shape by default.</summary>
    public const int DefaultTraces = 3;

    /// <summary>
    /// The ray a scene's exposure is traced on: the first camera ray of an 8x8 image whose full-range search marks a
    /// primitive (the first ray when none does). Other rays differ only in the depth register and the comparators'
    /// widths, a few percent of the circuit.
    /// </summary>
    public static OracleInput RepresentativeRay(Scene scene)
    {
        ArgumentNullException.ThrowIfNull(scene);
        var geometry = new SceneGeometry(scene);
        OracleInput? first = null;
        foreach (var ray in Rays.CameraRays.For(scene.Camera, 8, 8))
        {
            var table = RayTable.Build(geometry, ray);
            var input = new OracleInput(table, table.FullRange);
            first ??= input;
            if (table.Marked(table.FullRange).MarkedCount > 0) return input;
        }
        return first!;
    }

    /// <summary>The key a scene's circuit is known by: N and the coordinate bits.</summary>
    public static string KeyOf(int primitives, int coordinateBits) =>
        string.Create(CultureInfo.InvariantCulture, $"N={primitives},bits={coordinateBits}");

    public static string KeyOf(Scene scene) => KeyOf(scene.Primitives.Count, scene.Grid.Bits);

    public JsonObject ToJson()
    {
        var json = new JsonObject { ["shape"] = Shape, ["outside"] = Outside.ToJson(), ["iteration"] = Iteration.ToJson() };
        if (Outside.HarmToJson() is { } outside && Iteration.HarmToJson() is { } iteration)
        {
            json["outsideHarm"] = outside;
            json["iterationHarm"] = iteration;
            if (Estimate is { } estimate) json["harmEstimate"] = estimate.ToJson();
            if (Channels is { } channels) json["channels"] = channels.ToJson();
        }
        return json;
    }

    /// <summary>A table entry; graded harm below zero is refused (a harm is a share of the error's effect, never a gain).</summary>
    public static GateLevelExposure Parse(JsonNode node)
    {
        var shape = node["shape"]!.GetValue<string>();
        var exposure = new GateLevelExposure(shape, NoiseExposure.Parse(node["outside"]!, node["outsideHarm"]), NoiseExposure.Parse(node["iteration"]!, node["iterationHarm"]),
            node["harmEstimate"] is { } estimate ? HarmEstimate.Parse(estimate) : null,
            node["channels"] is { } channels ? SearchChannels.Parse(channels, shape) : null);
        foreach (var (part, harm) in new[] { ("outsideHarm", exposure.Outside.Harm), ("iterationHarm", exposure.Iteration.Harm) })
            foreach (var (kind, paulis) in harm ?? new Dictionary<string, IReadOnlyDictionary<string, double>>())
                foreach (var (pauli, h) in paulis)
                    if (!(h >= 0)) throw new InvalidDataException($"gate-level exposure of {shape}: {part}.{kind}.{pauli} is {h.ToString(CultureInfo.InvariantCulture)}, and a graded harm cannot be negative");
        return exposure;
    }
}
