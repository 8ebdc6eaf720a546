using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// The ray an estimate is made for: a camera ray's first search (its full range: every depth from the
/// ray's near onwards, every primitive id), chosen by pixel or as the scene's worst case.
/// </summary>
public static class EstimateRay
{
    /// <summary>The oracle input of the camera ray through pixel (x, y) of a width × height image.</summary>
    public static (OracleInput Input, string Label) Pixel(Scene scene, SceneGeometry geometry, int width, int height, int x, int y, OracleConstruction construction)
    {
        if (!geometry.RectanglesOnly)
            throw new Output.UserError($"scene {scene.Name}: the gate-level oracle takes rectangles only, and the scene holds triangles");
        var ray = CameraRays.For(scene.Camera, width, height)[y * width + x];
        var table = RayTable.Build(geometry, ray);
        return (new OracleInput(table, table.FullRange) { Construction = construction }, $"pixel ({x}, {y}) of {width}x{height}");
    }

    /// <summary>
    /// The worst case: of the camera rays of a width × height image, the one whose search needs the
    /// widest oracle (most peak qubits, <see cref="OracleRegisters.PeakQubits"/>); among equally wide
    /// ones the one with the most depth bits (the only register width that varies by ray), then the
    /// first in row-major pixel order. The index, coordinate and flag registers are the scene's; only the
    /// depth register and the comparators' auxiliaries differ between rays.
    /// </summary>
    public static (OracleInput Input, string Label) WorstCase(Scene scene, SceneGeometry geometry, int width, int height, OracleConstruction construction)
    {
        var rays = CameraRays.For(scene.Camera, width, height);
        var keys = new (int Peak, int Depth)[rays.Length];
        Parallel.For(0, rays.Length, k =>
        {
            var table = RayTable.Build(geometry, rays[k]);
            var registers = OracleRegisters.For(new OracleInput(table, table.FullRange) { Construction = construction });
            keys[k] = (registers.PeakQubits, registers.DepthQubits);
        });
        var best = 0;
        for (var k = 1; k < rays.Length; k++)
            if (keys[k].Peak > keys[best].Peak || (keys[k].Peak == keys[best].Peak && keys[k].Depth > keys[best].Depth)) best = k;
        var (input, label) = Pixel(scene, geometry, width, height, best % width, best / width, construction);
        return (input, $"worst case: {label}");
    }

    /// <summary>
    /// A pool of <paramref name="rays"/> camera rays of a width × height image for a pooled query, each in its first search
    /// (full range): the pixels k · (width · height) / rays, spread evenly in row-major order. A pooled query's gates depend
    /// on the pool's size, N and the widest ray's depth bits, not on which rays it holds (but for the constant-bound construction).
    /// </summary>
    public static (IReadOnlyList<OracleInput> Pool, string Label) Pool(Scene scene, SceneGeometry geometry, int width, int height, int rays, OracleConstruction construction)
    {
        var pixels = (long)width * height;
        if (rays < 1 || rays > pixels) throw new ArgumentOutOfRangeException(nameof(rays), $"a pool of {rays} rays from a {width}x{height} image's {pixels} camera rays");
        var camera = CameraRays.For(scene.Camera, width, height);
        var pool = Enumerable.Range(0, rays).AsParallel().AsOrdered().Select(k =>
        {
            var table = RayTable.Build(geometry, camera[(int)(k * pixels / rays)]);
            return new OracleInput(table, table.FullRange) { Construction = construction };
        }).ToList();
        return (pool, $"{rays} camera rays of {width}x{height}, spread evenly over the image, each its first search (full range)");
    }
}
