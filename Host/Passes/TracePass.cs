using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// TracePass (Algorithm 4): minimum finding over depth for primary or specular rays. Each round
/// searches every unfinished ray for a hit closer than its current one (QTrace, Algorithm 3) and keeps
/// what it finds; a ray is finished when the engine's answer is certain (the classical engines test
/// every primitive), so the classical reference costs one round.
/// </summary>
public static class TracePass
{
    public static (Hit?[] Hits, PassMetrics Metrics) Run(
        string name, IHitSearch search, SceneGeometry geometry, IReadOnlyList<Ray> rays, int iterations,
        TieBreak tieBreak, IRenderProgress? progress = null)
    {
        var hits = new Hit?[rays.Count];
        var metrics = IteratedSearch.Run(name, search, geometry, rays, iterations,
            (i, table) => hits[i] is { } hit ? HitWindow.Closer(rays[i].Near, hit.Depth, hit.Primitive, tieBreak) : table.FullRange,
            (i, table, outcome) =>
            {
                if (outcome.Primitive is { } p) hits[i] = Hit.From(table, p);
                return outcome.Certain;
            },
            progress);
        return (hits, metrics);
    }
}
