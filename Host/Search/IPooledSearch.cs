namespace QuantumRayTracing.Search;

/// <summary>
/// One QSearch over the pooled (ray, primitive) pairs of several ray searches: a pair is marked when its row is accepted
/// under its ray's window, so the search finds a ray that is wrong, if any is, in about √(rays · N) queries where
/// confirming each ray alone takes about rays · √N. Each query looks up its ray's window over the rays and the pair's row
/// over the rays × N pairs (a row's point depends on the ray as well as the primitive), and tests the pair (Q#
/// <c>ApplyPooledIntersectionOracle</c>): docs/conventions.md counts it as one query and gives its gates, which grow with the pool.
/// Only an engine that samples the search's outcome (the noiseless analytic engine) can run registers this wide.
/// </summary>
public interface IPooledSearch
{
    /// <summary>Whether this engine runs pooled searches.</summary>
    bool PoolsRays { get; }

    /// <summary>The schedule of a pooled search over <paramref name="rays"/> rays of <paramref name="count"/> primitives each.</summary>
    QSearchSchedule PooledSchedule(int rays, int count);

    /// <summary>One pooled search over <paramref name="queries"/> (every table of the same N, at most <see cref="MaxPairs"/> pairs); their own schedules are ignored.</summary>
    PooledOutcome RunPooled(IReadOnlyList<HitQuery> queries);

    /// <summary>The most pairs one pooled search holds: a 30-qubit index register.</summary>
    public const int MaxPairs = 1 << 30;
}

/// <summary>A pooled search's find, the query's position and the primitive, or none; and its cost.</summary>
public readonly record struct PooledOutcome(int? Query, int? Primitive, SearchCost Cost);
