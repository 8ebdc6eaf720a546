using System.Globalization;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Export;

/// <summary>
/// One ray's Grover search as an export: the uniform superposition over the ray's primitives, r iterations
/// of the gate-level oracle and the diffusion, the index register measured. Every format compiles Q#
/// <c>ApplyGateGroverSearchWithUnitaryLookups</c>: the search the gate engine runs
/// (<c>ApplyGateGroverSearch</c>) with its table lookups uncomputed by Toffoli gates instead of by measurement
/// and feedback (the QDK's QIR compile takes time quadratic in the number of feedback branches, and the
/// lookups hold most of them: 1,116 of 1,236 at N = 64), and its loads cleared by a second lookup for every
/// construction (the measured unlookup of compact, baseline and device stops the QDK's QIR compile).
/// </summary>
public static class SearchExport
{
    /// <summary>The search of the camera ray through pixel (x, y) of a width × height image of <paramref name="scene"/>.</summary>
    public static ExportSubject ForPixel(Scene scene, int width, int height, int x, int y, OracleConstruction construction, int? iterations)
    {
        if (scene.Primitives.Count < 2) throw new Output.UserError($"scene {scene.Name}: a search needs at least 2 primitives");
        var (input, label) = EstimateRay.Pixel(scene, new SceneGeometry(scene), width, height, x, y, construction);
        return Subject("qrt export search", scene.Name, $"camera ray through {label}", input, iterations);
    }

    /// <summary>The subject; <paramref name="iterations"/> null takes the optimal count for the ray's marked set.</summary>
    public static ExportSubject Subject(string command, string scene, string ray, OracleInput input, int? iterations)
    {
        var count = input.Table.Count;
        var marked = input.Table.Marked(input.Window);
        var r = iterations ?? GroverProbability.OptimalIterations(count, marked.MarkedCount);
        var qubits = OracleRegisters.For(input).IndexQubits;
        var construction = input.Construction;
        var indices = marked.MarkedCount == 0 ? "none" : string.Join(' ', marked.Indices.ToArray());
        return new ExportSubject(
            $"one ray's Grover search with the gate-level intersection oracle ({command})",
            [
                $"scene: {scene}, N = {count} primitives",
                $"ray: {ray}; marked primitives (hit window: the full range): {indices}",
                OracleLine(construction),
                $"iterations: {r}{(iterations is null ? $" ({DefaultIterationsReason(count, marked.MarkedCount)})" : "")}; P(marked) = {GroverProbability.OfMarked(count, marked.MarkedCount, r).ToString("R", CultureInfo.InvariantCulture)} by Grover's closed form",
                LookupsLine,
            ],
            $"{QSharpOperations.ApplyGateGroverSearchWithUnitaryLookups}({GateEngine.OracleArgument(input)}, {r.ToString(CultureInfo.InvariantCulture)}, _)",
            qubits,
            "index");
    }

    /// <summary>The header line that says how the table lookups uncompute (the form line says how the rest does).</summary>
    public const string LookupsLine = "table lookups: unary iteration, each AND uncomputed by a Toffoli gate (Q# ApplyGateGroverSearchWithUnitaryLookups; the gate engine's ApplyGateGroverSearch measures them instead, same state)";

    /// <summary>The header line of the construction; every export unloads by a second lookup (Q# ApplyGateGroverSearchWithUnitaryLookups).</summary>
    private static string OracleLine(OracleConstruction construction)
    {
        var line = $"oracle: {construction.Name} ({construction.Axes} axes tested, {construction.BoundRegisters} bound register(s)), unload by a second lookup";
        if (!construction.MeasuredUnload) return line;
        var same = construction == OracleConstruction.Compact ? "; so this is the narrow oracle's circuit" : "";
        return $"{line} (the engines' {construction.Name} oracle unloads by measurement, an unlookup the QDK cannot compile to QIR{same})";
    }

    /// <summary>
    /// Why the default count is what it is. With no primitive marked (a ray that hits nothing) or every one,
    /// no iteration changes the uniform distribution, so the default is the least circuit, none.
    /// </summary>
    private static string DefaultIterationsReason(int count, int marked) => marked switch
    {
        0 => "no primitive is marked: every r leaves the uniform distribution as it is, so none is run",
        _ when marked == count => "every primitive is marked: every r leaves the uniform distribution as it is, so none is run",
        _ => $"the optimum for {marked} of {count} marked",
    };
}
