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
        Span<int> neighbours = stackalloc int[4];
        Span<int> tried = stackalloc int[4];
        for (var i = 0; i < rays.Count; i++)
        {
            var triedCount = 0;
            var changed = false;
            Ray? read = null; // read at its first test: a pass's rays may be computed on each read
            var count = layout.Neighbours(i, neighbours);
            for (var n = 0; n < count; n++)
            {
                if (hits[neighbours[n]] is not { } held || hits[i]?.Primitive == held.Primitive || tried[..triedCount].Contains(held.Primitive)) continue;
                tried[triedCount++] = held.Primitive;
                var ray = read ??= rays[i];
                var window = Hit.Beyond(ray, hits[i], geometry.Count, tieBreak);
                tests++;
                if (RayTable.Test(geometry, ray, held.Primitive, window) is not { } row) continue;
                hits[i] = new Hit(held.Primitive, row.Depth, row.Distance, ray.At(row.Distance));
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
        Span<int> neighbours = stackalloc int[4];
        Span<int> tried = stackalloc int[4];
        for (var i = 0; i < rays.Count; i++)
        {
            if (occluders[i] is not null) continue;
            var triedCount = 0;
            Ray? read = null; // read at its first test, as above
            var count = layout.Neighbours(i, neighbours);
            for (var n = 0; n < count; n++)
            {
                if (occluders[neighbours[n]] is not { } held || tried[..triedCount].Contains(held)) continue;
                tried[triedCount++] = held;
                tests++;
                var ray = read ??= rays[i];
                if (RayTable.Test(geometry, ray, held, HitWindow.Range(ray.Near, ray.Far, geometry.Count)) is null) continue;
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
    /// result (one primitive, or all nothing) and the ray accepted that primitive. A level's rays read only coarser
    /// levels' hits, so they are gathered in parallel.
    /// </summary>
    public static (long Tests, long Updated) FromLattice(
        SceneGeometry geometry, IReadOnlyList<Ray> rays, int[] level, Hit?[] hits, PixelLayout layout, int levels, TieBreak tieBreak, bool[] agreed) =>
        InParallel(level, i =>
        {
            long tests = 0;
            Span<int> coarser = stackalloc int[PixelLayout.MostCoarserNeighbours];
            Span<int> distinct = stackalloc int[PixelLayout.MostCoarserNeighbours];
            var count = layout.CoarserNeighbours(i, levels, coarser);
            var (distinctCount, allSame) = (0, true);
            for (var n = 0; n < count; n++)
            {
                var held = hits[coarser[n]]?.Primitive;
                allSame &= held == hits[coarser[0]]?.Primitive;
                if (held is { } p && !distinct[..distinctCount].Contains(p)) distinct[distinctCount++] = p;
            }
            Ray? read = null; // read at its first test, as in ForClosest
            foreach (var p in distinct[..distinctCount])
            {
                var ray = read ??= rays[i];
                var window = Hit.Beyond(ray, hits[i], geometry.Count, tieBreak);
                tests++;
                if (RayTable.Test(geometry, ray, p, window) is not { } row) continue;
                hits[i] = new Hit(p, row.Depth, row.Distance, ray.At(row.Distance));
            }
            agreed[i] = count > 0 && count == layout.CoarserNeighbourSlots(i, levels) && allSame && hits[i]?.Primitive == hits[coarser[0]]?.Primitive;
            return (tests, hits[i] is not null);
        });

    /// <summary>
    /// Lattice-first tracing, shadow rays: every unoccluded ray of one lattice level is tested against
    /// its next-coarser lattice neighbours' occluders. It "agrees" when it has all its lattice neighbours and none is occluded.
    /// </summary>
    public static (long Tests, long Updated) FromLatticeOccluders(
        SceneGeometry geometry, IReadOnlyList<Ray> rays, int[] level, int?[] occluders, PixelLayout layout, int levels, bool[] agreed) =>
        InParallel(level, i =>
        {
            if (occluders[i] is not null) return (0, false);
            long tests = 0;
            var updated = false;
            Span<int> coarser = stackalloc int[PixelLayout.MostCoarserNeighbours];
            Span<int> tried = stackalloc int[PixelLayout.MostCoarserNeighbours];
            var (count, triedCount, noneOccluded) = (layout.CoarserNeighbours(i, levels, coarser), 0, true);
            Ray? read = null; // read at its first test, as in ForOcclusion
            for (var n = 0; n < count; n++)
            {
                if (occluders[coarser[n]] is not { } p) continue;
                noneOccluded = false;
                if (updated || tried[..triedCount].Contains(p)) continue;
                tried[triedCount++] = p;
                tests++;
                var ray = read ??= rays[i];
                if (RayTable.Test(geometry, ray, p, HitWindow.Range(ray.Near, ray.Far, geometry.Count)) is null) continue;
                occluders[i] = p;
                updated = true;
            }
            agreed[i] = count == layout.CoarserNeighbourSlots(i, levels) && noneOccluded;
            return (tests, updated);
        });

    // Gathers every ray of a level on all cores: each ray writes only its own entries, and the counts are summed.
    private static (long Tests, long Updated) InParallel(int[] level, Func<int, (long Tests, bool Updated)> gather)
    {
        long tests = 0, updated = 0;
        if (level.Length == 0) return (0, 0);
        Parallel.ForEach(System.Collections.Concurrent.Partitioner.Create(0, level.Length, 4096), () => (0L, 0L), (range, _, sums) =>
        {
            for (var k = range.Item1; k < range.Item2; k++)
            {
                var (t, u) = gather(level[k]);
                sums = (sums.Item1 + t, sums.Item2 + (u ? 1 : 0));
            }
            return sums;
        }, sums =>
        {
            Interlocked.Add(ref tests, sums.Item1);
            Interlocked.Add(ref updated, sums.Item2);
        });
        return (tests, updated);
    }
}
