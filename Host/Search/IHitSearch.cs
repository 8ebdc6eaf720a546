namespace QuantumRayTracing.Search;

/// <summary>
/// The seam the ray passes search through: a batch of ray searches in, one outcome per search out,
/// in order. The quantum engines answer with QSearch (<see cref="QuantumHitSearch"/>), the classical
/// ones by testing primitives directly; the passes above are the same for all.
/// </summary>
public interface IHitSearch : IDisposable
{
    /// <summary>The engine's name as chosen on the command line.</summary>
    string Name { get; }

    /// <summary>Runs every search; <paramref name="onRound"/> gets (round, searches still active) after each engine call.</summary>
    IReadOnlyList<HitOutcome> Run(IReadOnlyList<HitQuery> queries, Action<int, int>? onRound = null);

    /// <summary>
    /// The estimated probability that one search over <paramref name="count"/> primitives reports nothing
    /// although some are accepted, for t distributed as <paramref name="pt"/> (indexed by t): the p̄ of the
    /// termination criterion (sec. 6.2). <paramref name="paperFormula"/> asks for the paper's estimate
    /// (eq. 10 at r = M_l, eq. 11) instead of the exact rate where they differ; <paramref name="schedule"/>,
    /// when set, is the QSearch schedule the searches use instead of the engine's own.
    /// </summary>
    double MissProbability(int count, IReadOnlyList<double> pt, bool paperFormula, QSearchSchedule? schedule = null);

    /// <summary>
    /// The exact miss probability on the machine the searches run on (<see cref="MissProbability"/> without the paper's
    /// formula): a noisy machine's even when the passes plan with the ideal one, so the expected wrong pixels a render reports
    /// predict what it measures.
    /// </summary>
    double MachineMissProbability(int count, IReadOnlyList<double> pt, QSearchSchedule? schedule = null) => MissProbability(count, pt, paperFormula: false, schedule);

    /// <summary>Whether <see cref="MachineMissProbability"/> differs from the misses the passes plan with (a noisy render planned as ideal).</summary>
    bool MachineMissesDiffer => false;

    /// <summary>
    /// The expected #Int (conservative count) of one search over <paramref name="count"/> primitives that finds
    /// nothing: what a further confirming search costs at most, for the classical settle (docs/conventions.md).
    /// <paramref name="schedule"/>, when set, is the QSearch schedule used instead of the engine's own.
    /// </summary>
    double EmptySearchCost(int count, QSearchSchedule? schedule = null);
}
