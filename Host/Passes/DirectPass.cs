using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// DirectPass (appendix B, Algorithm 6): light visibility. Each round runs QOccluded (any hit in the
/// shadow ray's range, no minimisation) for every shadow ray not yet found occluded; a ray is finished
/// once occluded or once an engine's answer is certain. The paper uses two rounds: the second catches
/// most of QSearch's false negatives.
/// </summary>
public static class DirectPass
{
    public const int DefaultIterations = 2;

    public static (bool[] Occluded, PassMetrics Metrics) Run(
        string name, IHitSearch search, SceneGeometry geometry, IReadOnlyList<Ray> shadowRays, int iterations,
        IRenderProgress? progress = null)
    {
        var occluded = new bool[shadowRays.Count];
        var metrics = IteratedSearch.Run(name, search, geometry, shadowRays, iterations,
            (_, table) => table.FullRange,
            (i, _, outcome) =>
            {
                occluded[i] = outcome.Primitive is not null;
                return occluded[i] || outcome.Certain;
            },
            progress);
        return (occluded, metrics);
    }
}
