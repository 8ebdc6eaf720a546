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
/// (<see cref="Iteration"/>), from the circuits the QDK extracts with no iteration and with one and two (the difference
/// of the last two is one iteration, as for the estimates). Z and CZ counts vary slightly with the measurement-based
/// uncomputation's outcomes; the traced runs' are kept.
/// </summary>
/// <param name="Shape">What the circuit was traced for: N, coordinate bits and the ray, in words.</param>
/// <param name="Outside">The preparation and the index measurement.</param>
/// <param name="Iteration">One Grover iteration: the phase oracle and the reflection.</param>
public sealed record GateLevelExposure(string Shape, NoiseExposure Outside, NoiseExposure Iteration)
{
    /// <summary>The exposure of a run with <paramref name="iterations"/> Grover iterations.</summary>
    public NoiseExposure Run(int iterations) => Outside + (double)iterations * Iteration;

    private readonly System.Collections.Concurrent.ConcurrentDictionary<NoiseModel, (double Outside, double Iteration)> _logFidelities = new();

    /// <summary>Φ = F₀ · F^r of a run with <paramref name="iterations"/> iterations, F₀ and F computed once per noise model.</summary>
    public double RunFidelity(NoiseModel noise, int iterations)
    {
        var (outside, iteration) = _logFidelities.GetOrAdd(noise, n => (Math.Log(Outside.Fidelity(n)), Math.Log(Iteration.Fidelity(n))));
        return Math.Min(1.0, Math.Exp(outside + iterations * iteration));
    }

    /// <summary>Traces <paramref name="input"/>'s search with r = 0, 1 and 2 on <paramref name="pool"/>'s bridges.</summary>
    /// <remarks>
    /// The locations by pattern: the preparation and measurement from r = 0, an iteration as r = 2 less r = 1. The graded
    /// harm depends on r (an error after the last diffusion does nothing, one in an early iteration is amplified with the
    /// run), so it is extrapolated from the runs that have it: an iteration as r = 2 less r = 1, the rest as r = 1 less
    /// that, which makes Φ exact for r = 1 and 2 on the traced ray and linear in r beyond.
    /// </remarks>
    /// <param name="pool">The bridges that trace the circuits.</param>
    /// <param name="input">The ray's oracle input; its marked set grades the harm.</param>
    /// <param name="shape">What the circuit was traced for, in words.</param>
    /// <param name="graded">Whether to grade the harm (Quantum/noise-harm.mjs; its time grows as the square of the circuit).</param>
    public static GateLevelExposure Trace(BridgePool pool, OracleInput input, string shape, bool graded = true)
    {
        ArgumentNullException.ThrowIfNull(pool);
        ArgumentNullException.ThrowIfNull(input);
        var argument = GateEngine.OracleArgument(input);
        int[]? marked = graded ? input.Table.Marked(input.Window).Indices.ToArray() : null;
        // Graded, r = 1 and 2 are traced twice each: a trace's measured outcomes decide which corrections it holds, and where
        // the grading cannot pair one with its measurement it counts the error whole; the less harmful reading is kept.
        (int R, int Copy)[] runs = graded ? [(2, 0), (2, 1), (1, 0), (1, 1), (0, 0)] : [(2, 0), (1, 0), (0, 0)];
        var readings = new NoiseExposure[3, 2];
        pool.ForEach(runs, (run, bridge) =>
        {
            var summary = bridge.Circuit($"{QSharpOperations.MeasureGateGroverSearch}({argument}, {run.R.ToString(CultureInfo.InvariantCulture)})", timeout: TimeSpan.FromMinutes(30), exposure: true, marked: marked);
            readings[run.R, run.Copy] = NoiseExposure.Parse(summary["exposure"]!, summary["harm"]);
        });
        // A run's second reading replaces its first where it is graded and less harmful (or the first is not graded).
        static bool Better(NoiseExposure? other, NoiseExposure first) =>
            other is { Harm: not null } && (first.Harm is null || other.HarmWeight < first.HarmWeight);
        var traced = Enumerable.Range(0, 3).Select(r => Better(readings[r, 1], readings[r, 0]) ? readings[r, 1] : readings[r, 0]).ToArray();
        var iteration = traced[2] - traced[1];
        return new GateLevelExposure(shape, graded ? traced[0] with { Harm = (traced[1] - iteration).Harm } : traced[0], iteration);
    }

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

    public static string KeyOf(Scene scene) => KeyOf(scene.Rectangles.Count, scene.Grid.Bits);

    public JsonObject ToJson()
    {
        var json = new JsonObject { ["shape"] = Shape, ["outside"] = Outside.ToJson(), ["iteration"] = Iteration.ToJson() };
        if (Outside.HarmToJson() is { } outside && Iteration.HarmToJson() is { } iteration)
        {
            json["outsideHarm"] = outside;
            json["iterationHarm"] = iteration;
        }
        return json;
    }

    public static GateLevelExposure Parse(JsonNode node) =>
        new(node["shape"]!.GetValue<string>(), NoiseExposure.Parse(node["outside"]!, node["outsideHarm"]), NoiseExposure.Parse(node["iteration"]!, node["iterationHarm"]));
}
