using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// TracePass (Algorithm 4): minimum finding over depth for primary or specular rays. Each round
/// searches every unfinished ray for a hit closer than its current one (QTrace, Algorithm 3) and keeps
/// what it finds; then, with a layout, NeighOpt (Algorithm 5) tests each ray against its neighbours'
/// primitives. A ray is finished when the engine's answer is certain (the classical engines test every
/// primitive, so the classical reference costs one round) or when the stop rule ends it after a miss.
/// </summary>
public static class TracePass
{
    public static (Hit?[] Hits, PassMetrics Metrics) Run(
        string name, IHitSearch search, SceneGeometry geometry, IReadOnlyList<Ray> rays, PassOptions options,
        IRenderProgress? progress = null)
    {
        var hits = new Hit?[rays.Count];
        var misses = new int[rays.Count];
        var metrics = IteratedSearch.Run(name, search, geometry, rays, options.Iterations,
            (i, table) => hits[i] is { } hit ? HitWindow.Closer(rays[i].Near, hit.Depth, hit.Primitive, options.TieBreak) : table.FullRange,
            (i, table, outcome) =>
            {
                if (outcome.Primitive is { } p) hits[i] = Hit.From(table, p);
                misses[i] = outcome.Primitive is null ? misses[i] + 1 : 0;
                return outcome.Certain || options.Stop?.Continue(misses[i]) == false;
            },
            progress,
            options.Neighbours is { } layout ? () => NeighbourGathering.ForClosest(geometry, rays, hits, layout, options.TieBreak) : null);
        return (hits, metrics);
    }
}
