using System.Globalization;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Export;

/// <summary>
/// A pooled search as an export: the uniform superposition over the pool's (ray, primitive) pairs, r pooled Grover
/// iterations (each pair's row and its ray's window looked up, the one-ray oracle's comparators, the reflection about the
/// pairs), the pair register measured. It compiles Q# <c>ApplyPooledGroverSearchWithUnitaryLookups</c>: every lookup
/// uncomputed by Toffoli gates and every load cleared by a second lookup, as <see cref="SearchExport"/> does for one ray.
/// </summary>
public static class PooledSearchExport
{
    /// <summary>The pooled search of the camera rays through <paramref name="pixels"/> of a width × height image, each in its full range.</summary>
    public static ExportSubject ForPixels(Scene scene, int width, int height, IReadOnlyList<(int X, int Y)> pixels, OracleConstruction construction, int? iterations)
    {
        if (scene.Primitives.Count < 2) throw new Output.UserError($"scene {scene.Name}: a search needs at least 2 primitives");
        if (pixels.Distinct().Count() != pixels.Count) throw new Output.UserError("--pixels: a pixel is named twice; a pool holds each ray once");
        var geometry = new SceneGeometry(scene);
        var pool = pixels.Select(p => EstimateRay.Pixel(scene, geometry, width, height, p.X, p.Y, construction).Input).ToArray();
        var count = geometry.Count;
        var n = geometry.IndexBits;
        var rayBits = pool.Length <= 1 ? 0 : 32 - int.LeadingZeroCount(pool.Length - 1);
        // Pair (ray k, primitive p) is the register value k · 2^n + p.
        var marked = pool.SelectMany((input, k) => input.Table.Marked(input.Window).Indices.ToArray().Select(p => (k << n) + p)).ToArray();
        var pairs = pool.Length * count;
        var r = iterations ?? GroverProbability.OptimalIterations(pairs, marked.Length);
        var rays = string.Join(", ", pixels.Select(p => $"({p.X}, {p.Y})"));
        return new ExportSubject(
            "a pooled Grover search over several rays' (ray, primitive) pairs with the gate-level intersection oracle (qrt export pooled-search)",
            [
                $"scene: {scene.Name}, N = {count} primitives",
                $"pool: the camera rays through pixels {rays} of {width}x{height}, each its first search (full range); {pairs} pairs, pair register {n} primitive + {rayBits} ray qubits, value ray · {1 << n} + primitive",
                $"marked pairs: {(marked.Length == 0 ? "none" : string.Join(' ', marked))}",
                $"oracle: {construction.Name} ({construction.Axes} axes tested, {construction.BoundRegisters} bound register(s)), every load cleared by a second lookup",
                $"iterations: {r}; P(marked) = {GroverProbability.OfMarked(pairs, marked.Length, r).ToString("R", CultureInfo.InvariantCulture)} by Grover's closed form over the {pairs} pairs",
                "table lookups: unary iteration, each AND uncomputed by a Toffoli gate (Q# ApplyPooledGroverSearchWithUnitaryLookups)",
            ],
            $"{QSharpOperations.ApplyPooledGroverSearchWithUnitaryLookups}({GateEngine.PooledArgument(pool)}, {r.ToString(CultureInfo.InvariantCulture)}, _)",
            n + rayBits,
            "pair");
    }
}
