using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// The distribution of t a scene's searches meet, measured classically on a lattice of primary rays
/// (every <see cref="Spacing"/>-th pixel in x and y): for each sampled ray with k accepted primitives in
/// (depth, id) order, a search with no hit yet has t = k, and one whose current hit is the j-th has
/// t = j − 1 closer ones (counted only when j &gt; 1, t = 0 is not a miss). Its N tests per sampled ray
/// are reported as their own pass, with no rays of its own: the sampled rays are primary rays.
/// </summary>
public static class SceneTDistribution
{
    public const int Spacing = 8;

    public static (double[] Pt, PassMetrics Metrics) Measure(SceneGeometry geometry, IReadOnlyList<Ray> primaryRays, int width, int height)
    {
        var clock = System.Diagnostics.Stopwatch.StartNew();
        var counts = new long[geometry.Count + 1];
        long rays = 0;
        for (var y = Spacing / 2; y < height; y += Spacing)
            for (var x = Spacing / 2; x < width; x += Spacing)
            {
                var table = RayTable.Build(geometry, primaryRays[y * width + x]);
                var accepted = table.Marked(table.FullRange).MarkedCount;
                rays++;
                if (accepted == 0) continue;
                counts[accepted]++;
                for (var t = 1; t < accepted; t++) counts[t]++;
            }
        var total = counts.Sum();
        var pt = total == 0
            ? FalseNegativeRate.Uniform(geometry.Count, geometry.Count)
            : counts.Select(c => (double)c / total).ToArray();
        return (pt, new PassMetrics("calibration", 0, 1, new SearchCost(0, 0, rays * geometry.Count, 0), rays * geometry.Count, clock.Elapsed));
    }
}
