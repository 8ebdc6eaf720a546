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
        return Math.Exp(outside + iterations * iteration);
    }

    /// <summary>Traces <paramref name="input"/>'s search with r = 0, 1 and 2 on <paramref name="pool"/>'s bridges.</summary>
    /// <remarks>
    /// An error late in a run's last iteration harms less often than one with iterations after it; the iteration is
    /// counted as one with iterations after it (the difference of r = 2 and r = 1), so a run's last iteration is
    /// counted on the harmful side.
    /// </remarks>
    public static GateLevelExposure Trace(BridgePool pool, OracleInput input, string shape)
    {
        ArgumentNullException.ThrowIfNull(pool);
        var argument = GateEngine.OracleArgument(input);
        var traced = new NoiseExposure[3];
        pool.ForEach([2, 1, 0], (r, bridge) =>
            traced[r] = NoiseExposure.Parse(bridge.Circuit($"{QSharpOperations.MeasureGateGroverSearch}({argument}, {r.ToString(CultureInfo.InvariantCulture)})", timeout: TimeSpan.FromMinutes(30), exposure: true)["exposure"]!));
        return new GateLevelExposure(shape, traced[0], traced[2] - traced[1]);
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

    public JsonObject ToJson() => new() { ["shape"] = Shape, ["outside"] = Outside.ToJson(), ["iteration"] = Iteration.ToJson() };

    public static GateLevelExposure Parse(JsonNode node) =>
        new(node["shape"]!.GetValue<string>(), NoiseExposure.Parse(node["outside"]!), NoiseExposure.Parse(node["iteration"]!));
}
