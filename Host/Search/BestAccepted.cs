using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Search;

/// <summary>The classical engines' choice among tested primitives: the smallest (depth, id) that verify-rpc accepts.</summary>
public static class BestAccepted
{
    public static int? Among(RayTable table, HitWindow window, IEnumerable<int> tested)
    {
        int? best = null;
        foreach (var p in tested)
        {
            if (!table.Verify(p, window)) continue;
            if (best is not { } b || table.Depth(p) < table.Depth(b) || (table.Depth(p) == table.Depth(b) && p < b))
                best = p;
        }
        return best;
    }
}
