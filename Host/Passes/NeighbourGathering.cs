using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;

namespace QuantumRayTracing.Passes;

/// <summary>
/// NeighOpt (Algorithm 5): after a round, each ray is tested classically against the primitives its
/// 4 neighbours currently hold, in scan order and in place, so a found minimum spreads through a
/// region in one sweep. Every test counts in #C_Int, every ray it changes in #Cpix.
/// </summary>
public static class NeighbourGathering
{
    /// <summary>Closest hits: a neighbour's primitive replaces the ray's hit if it comes first in the window's order.</summary>
    public static (long Tests, long Updated) ForClosest(
        SceneGeometry geometry, IReadOnlyList<Ray> rays, Hit?[] hits, PixelLayout layout, TieBreak tieBreak)
    {
        long tests = 0, updated = 0;
        var tried = new HashSet<int>();
        for (var i = 0; i < rays.Count; i++)
        {
            tried.Clear();
            var changed = false;
            foreach (var neighbour in layout.Neighbours(i))
            {
                if (hits[neighbour] is not { } held || hits[i]?.Primitive == held.Primitive || !tried.Add(held.Primitive)) continue;
                var window = Hit.Beyond(rays[i], hits[i], geometry.Count, tieBreak);
                tests++;
                if (RayTable.Test(geometry, rays[i], held.Primitive, window) is not { } row) continue;
                hits[i] = new Hit(held.Primitive, row.Depth, row.Distance, rays[i].At(row.Distance));
                changed = true;
            }
            if (changed) updated++;
        }
        return (tests, updated);
    }

    /// <summary>Shadow rays: an unoccluded ray is tested against its neighbours' occluders (the paper's future work).</summary>
    public static (long Tests, long Updated) ForOcclusion(
        SceneGeometry geometry, IReadOnlyList<Ray> rays, int?[] occluders, PixelLayout layout)
    {
        long tests = 0, updated = 0;
        var tried = new HashSet<int>();
        for (var i = 0; i < rays.Count; i++)
        {
            if (occluders[i] is not null) continue;
            tried.Clear();
            foreach (var neighbour in layout.Neighbours(i))
            {
                if (occluders[neighbour] is not { } held || !tried.Add(held)) continue;
                tests++;
                if (RayTable.Test(geometry, rays[i], held, HitWindow.Range(rays[i].Near, rays[i].Far, geometry.Count)) is null) continue;
                occluders[i] = held;
                updated++;
                break;
            }
        }
        return (tests, updated);
    }

    /// <summary>
    /// Lattice-first tracing, closest hits: every ray of one lattice level is tested against the
    /// primitives its next-coarser lattice neighbours hold. It "agrees" when it has all its lattice neighbours (a ray at the
    /// border, or beside pixels without a ray of its channel, has fewer and gets a full search), they all hold the same
    /// result (one primitive, or all nothing) and the ray accepted that primitive.
    /// </summary>
    public static (long Tests, long Updated) FromLattice(
        SceneGeometry geometry, IReadOnlyList<Ray> rays, IEnumerable<int> level, Hit?[] hits, PixelLayout layout, int levels, TieBreak tieBreak, bool[] agreed)
    {
        long tests = 0, updated = 0;
        foreach (var i in level)
        {
            var held = layout.CoarserNeighbours(i, levels).Select(j => hits[j]?.Primitive).ToArray();
            foreach (var p in held.OfType<int>().Distinct())
            {
                var window = Hit.Beyond(rays[i], hits[i], geometry.Count, tieBreak);
                tests++;
                if (RayTable.Test(geometry, rays[i], p, window) is not { } row) continue;
                hits[i] = new Hit(p, row.Depth, row.Distance, rays[i].At(row.Distance));
            }
            if (hits[i] is not null) updated++;
            agreed[i] = held.Length == layout.CoarserNeighbourSlots(i, levels) && held.Distinct().Count() == 1 && hits[i]?.Primitive == held[0];
        }
        return (tests, updated);
    }

    /// <summary>
    /// Lattice-first tracing, shadow rays: every unoccluded ray of one lattice level is tested against
    /// its next-coarser lattice neighbours' occluders. It "agrees" when it has all its lattice neighbours and none is occluded.
    /// </summary>
    public static (long Tests, long Updated) FromLatticeOccluders(
        SceneGeometry geometry, IReadOnlyList<Ray> rays, IEnumerable<int> level, int?[] occluders, PixelLayout layout, int levels, bool[] agreed)
    {
        long tests = 0, updated = 0;
        foreach (var i in level)
        {
            if (occluders[i] is not null) continue;
            var held = layout.CoarserNeighbours(i, levels).Select(j => occluders[j]).ToArray();
            foreach (var p in held.OfType<int>().Distinct())
            {
                tests++;
                if (RayTable.Test(geometry, rays[i], p, HitWindow.Range(rays[i].Near, rays[i].Far, geometry.Count)) is null) continue;
                occluders[i] = p;
                updated++;
                break;
            }
            agreed[i] = held.Length == layout.CoarserNeighbourSlots(i, levels) && held.All(o => o is null);
        }
        return (tests, updated);
    }
}
