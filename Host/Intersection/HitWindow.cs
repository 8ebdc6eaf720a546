namespace QuantumRayTracing.Intersection;

/// <summary>
/// Which (depth, primitive) pairs a search accepts: depth ≥ <see cref="Near"/> and
/// (depth, id) &lt; (<see cref="LimitDepth"/>, <see cref="LimitId"/>) in lexicographic order. One
/// window covers every search of the renderer: a ray's full range (limit (Far, N): depth ≤ Far), a
/// closer hit than the current best in the strict order (limit (best depth, best id), docs/conventions.md),
/// and the paper's random tie-breaking (limit (best depth, 0): strictly smaller depth).
/// </summary>
public readonly record struct HitWindow(int Near, int LimitDepth, int LimitId)
{
    public bool Accepts(int depth, int id) =>
        depth >= Near && (depth < LimitDepth || (depth == LimitDepth && id < LimitId));

    /// <summary>Every depth in [near, far] and every primitive id below <paramref name="count"/>.</summary>
    public static HitWindow Range(int near, int far, int count) => new(near, far, count);

    /// <summary>Hits that beat (<paramref name="bestDepth"/>, <paramref name="bestId"/>) under <paramref name="tieBreak"/>.</summary>
    public static HitWindow Closer(int near, int bestDepth, int bestId, TieBreak tieBreak) =>
        new(near, bestDepth, tieBreak == TieBreak.Strict ? bestId : 0);
}
