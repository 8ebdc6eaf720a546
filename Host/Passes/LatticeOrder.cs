namespace QuantumRayTracing.Passes;

/// <summary>
/// Runs a pass level by level over its lattice, coarsest first: each level's phase gets its rays and
/// an agreement flag per ray to fill, and the pass's progress scaled to its share of the rays; the
/// phases' metrics are joined into the pass's.
/// </summary>
public static class LatticeOrder
{
    public delegate (PassMetrics Searched, long Tests, long Updated) Phase(int level, int[] levelRays, bool[] agreed, IRenderProgress? progress);

    public static PassMetrics Run(int rays, PixelLayout layout, int levels, IRenderProgress? progress, Phase phase)
    {
        var agreed = new bool[rays];
        var byLevel = ByLevel(rays, layout, levels);
        PassMetrics? total = null;
        var before = 0;
        for (var level = levels; level >= 0; level--)
        {
            var levelRays = byLevel[level];
            var part = progress is null ? null : new PartProgress(progress, (double)before / Math.Max(1, rays), (double)levelRays.Length / Math.Max(1, rays));
            before += levelRays.Length;
            var (searched, tests, updated) = phase(level, levelRays, agreed, part);
            total = total is null
                ? searched with { Cost = searched.Cost + new Search.SearchCost(0, 0, tests, 0), UpdatedPixels = searched.UpdatedPixels + updated }
                : PassMetrics.Phases(total, searched, tests, updated);
        }
        return total!;
    }

    // Each level's rays in ascending order: counted first, then filled, without grouping every ray through a lookup.
    private static int[][] ByLevel(int rays, PixelLayout layout, int levels)
    {
        var level = new int[rays];
        var counts = new int[levels + 1];
        for (var i = 0; i < rays; i++) counts[level[i] = layout.LatticeLevel(i, levels)]++;
        var byLevel = counts.Select(n => new int[n]).ToArray();
        var filled = new int[levels + 1];
        for (var i = 0; i < rays; i++) byLevel[level[i]][filled[level[i]]++] = i;
        return byLevel;
    }
}
