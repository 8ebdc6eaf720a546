using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// DirectPass (appendix B, Algorithm 6): light visibility. Each round runs QOccluded (any hit in the
/// shadow ray's range, no minimisation) for every shadow ray not yet found occluded; then, with a
/// layout, each unoccluded ray is tested against its neighbours' occluders. A ray is finished once
/// occluded, once an engine's answer is certain, or when the stop rule ends it after a miss. The paper
/// uses two rounds: the second catches most of QSearch's false negatives.
/// </summary>
public static class DirectPass
{
    public const int DefaultIterations = 2;

    public static (bool[] Occluded, PassMetrics Metrics) Run(
        string name, IHitSearch search, SceneGeometry geometry, IReadOnlyList<Ray> shadowRays, PassOptions options,
        IRenderProgress? progress = null)
    {
        var occluders = new int?[shadowRays.Count];
        var misses = new int[shadowRays.Count];
        var metrics = IteratedSearch.Run(name, search, geometry, shadowRays, options.Iterations,
            (_, table) => table.FullRange,
            (i, _, outcome) =>
            {
                occluders[i] ??= outcome.Primitive;
                misses[i] = outcome.Primitive is null ? misses[i] + 1 : 0;
                return occluders[i] is not null || outcome.Certain || options.Stop?.Continue(misses[i]) == false;
            },
            progress,
            options.Neighbours is { } layout ? () => NeighbourGathering.ForOcclusion(geometry, shadowRays, occluders, layout) : null,
            i => occluders[i] is not null);
        return ([.. occluders.Select(o => o is not null)], metrics);
    }
}
