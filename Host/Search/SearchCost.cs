namespace QuantumRayTracing.Search;

/// <summary>
/// What searches cost, in the conventions of docs/conventions.md. Oracle queries (#Eval) come in two counts:
/// conservative, where a Grover run with r ≥ 1 iterations costs r + 1 (r applications of Q plus the
/// preparation A), and the paper's, where it costs r. Sampling the uniform superposition (r = 0)
/// costs no query in either. <see cref="ClassicalTests"/> is #C_Int, the classical verifications.
/// </summary>
public readonly record struct SearchCost(long QueriesConservative, long QueriesPaper, long ClassicalTests, long GroverRuns)
{
    public static SearchCost OfGroverRun(int iterations) =>
        iterations == 0 ? new(0, 0, 0, 1) : new(iterations + 1, iterations, 0, 1);

    public static SearchCost OfClassicalTest => new(0, 0, 1, 0);

    public static SearchCost operator +(SearchCost a, SearchCost b) =>
        new(a.QueriesConservative + b.QueriesConservative, a.QueriesPaper + b.QueriesPaper,
            a.ClassicalTests + b.ClassicalTests, a.GroverRuns + b.GroverRuns);

    /// <summary>
    /// The expected #Int (conservative) of a QSearch that finds nothing: every run of the schedule, each with its
    /// classical test; Algorithm 1 adds the initial sample (a test, no query) and draws r uniformly on 1..M_l.
    /// </summary>
    public static double ExpectedEmpty(QSearchSchedule schedule) => schedule.IsFixed
        ? schedule.Bounds.Sum(r => r + 2.0)
        : 1 + schedule.Bounds.Sum(m => (m + 1) / 2.0 + 2);
}
