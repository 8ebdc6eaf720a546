using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// One pass's record of every ray's searches, for the expected number of rays it leaves wrong. A ray is in an
/// "episode" until a search finds something (a closer hit; for a shadow ray, an occluder, which ends it); the
/// last episode ends with the ray's trailing empty searches, each missing with at most its schedule's worst miss
/// m for t = 1..<see cref="ConfirmationPlanner.MaxT"/>, so an episode that had something to find
/// ends wrong with probability at most W = ∏ m. With π the share of episodes that have something to find,
/// estimated per stratum from how often that stratum's searches found something (with half a find more, so a
/// stratum that found nothing is not taken for right), a ray is wrong with probability π W / (1 − π + π W), the
/// posterior given its trailing misses. The strata are fixed before an episode's searches: the ray's path (first
/// searched with the lattice's cheap confirmation, or not), whether the episode began with the ray's first search
/// or after a find (minimum finding: a ray that has just found a closer hit often has another closer still, a ray
/// its neighbours predicted seldom has) and, for a cheap confirmation, the ray's lattice level (its agreeing neighbours
/// 2^level pixels away: the nearer they are, the less often they mislead, and the budget rounds then search again
/// only the levels whose finds ask for it).
/// Summed over a stratum before any budget round this is about the stratum's finds · W / (1 − W); it errs high: every wrong ray counts as a wrong pixel, and neighbour gathering repairs nothing.
/// A certain answer (a classical test of every primitive) is never wrong.
/// The plan's expectation takes the worst misses the passes plan with; the machine's (<see cref="MachineExpectedTotal"/>) those of
/// the machine the searches run on, which differ only when a noisy render plans with the ideal miss rates (`render --ideal-plan`).
/// </summary>
public sealed class RayLedger
{
    /// <summary>The largest share of episodes taken to have something left: below 1, so trailing misses always count.</summary>
    public const double PriorCap = 0.99;

    private const int Unsearched = 0, CheapPath = 1, FullPath = 2;

    // The full path's first episodes and those after a find, the cheap path's episodes after a find, then the cheap
    // path's first episodes, one stratum per lattice level: a ray whose agreeing neighbours are nearer is less often misled.
    private const int FullFirst = 0, FullAfterFind = 1, CheapAfterFind = 2, CheapFirst = 3;

    private readonly double[] _trailing;
    private readonly double[] _machineTrailing;
    private readonly double[] _machinePrior;
    private readonly Func<QSearchSchedule?, double>? _machineWorstMiss;
    private readonly int[] _path;
    private readonly bool[] _done;
    private readonly bool[] _afterFind;
    private readonly IReadOnlyList<int>? _levels;
    private readonly long[] _found;
    private readonly double[] _prior;
    private readonly Func<QSearchSchedule?, double> _worstMiss;
    private readonly CheapConfirmation? _cheap;
    private readonly bool _findEnds;
    private bool _frozen;

    /// <param name="rays">The pass's rays.</param>
    /// <param name="worstMiss">A schedule's worst miss for t ≤ 8 (null: the engine's own schedule).</param>
    /// <param name="cheap">The lattice's cheap confirmation, whose rays form their own path, or null.</param>
    /// <param name="findEnds">Whether a find settles the ray (visibility) rather than start a search for a closer one.</param>
    /// <param name="levels">Each ray's lattice level, whose cheap confirmations form a stratum of their own; null: one level.</param>
    /// <param name="machineWorstMiss">The machine's worst misses where they differ from <paramref name="worstMiss"/>; null: the same.</param>
    public RayLedger(int rays, Func<QSearchSchedule?, double> worstMiss, CheapConfirmation? cheap, bool findEnds, IReadOnlyList<int>? levels = null,
        Func<QSearchSchedule?, double>? machineWorstMiss = null)
    {
        _levels = levels;
        var strata = CheapFirst + 1 + (levels is null || levels.Count == 0 ? 0 : levels.Max());
        _found = new long[strata];
        _prior = new double[strata];
        _trailing = Enumerable.Repeat(1.0, rays).ToArray();
        _machineWorstMiss = machineWorstMiss;
        _machineTrailing = machineWorstMiss is null ? _trailing : Enumerable.Repeat(1.0, rays).ToArray();
        _machinePrior = machineWorstMiss is null ? _prior : new double[strata];
        _path = new int[rays];
        _done = new bool[rays];
        _afterFind = new bool[rays];
        _worstMiss = worstMiss;
        _cheap = cheap;
        _findEnds = findEnds;
    }

    /// <summary>A ledger whose worst misses are the engine's, for N = <paramref name="count"/>, computed once per schedule.</summary>
    public static RayLedger For(int rays, IHitSearch search, int count, CheapConfirmation? cheap, bool findEnds, IReadOnlyList<int>? levels = null) =>
        new(rays, WorstMisses(search, count), cheap, findEnds, levels);

    /// <summary>
    /// A schedule's worst miss for t ≤ 8 (null: the engine's own), computed once per schedule: the plan's, or with
    /// <paramref name="machine"/> the machine's (<see cref="IHitSearch.MachineMissProbability"/>).
    /// </summary>
    public static Func<QSearchSchedule?, double> WorstMisses(IHitSearch search, int count, bool machine = false)
    {
        var known = new Dictionary<QSearchSchedule, double>();
        double? own = null;
        return schedule =>
        {
            if (schedule is null) return own ??= ConfirmationPlanner.WorstMiss(search, count, null, machine);
            if (!known.TryGetValue(schedule, out var miss)) known[schedule] = miss = ConfirmationPlanner.WorstMiss(search, count, schedule, machine);
            return miss;
        };
    }

    public int Rays => _trailing.Length;

    /// <summary>#Int (conservative) of the lattice's cheap confirmations before the budget rounds.</summary>
    public long CheapIntersections { get; private set; }

    /// <summary>Takes one search of <paramref name="ray"/> with <paramref name="schedule"/> and its outcome.</summary>
    public void Record(int ray, QSearchSchedule? schedule, HitOutcome outcome)
    {
        var cheap = _cheap?.Contains(schedule) == true;
        if (_path[ray] == Unsearched) _path[ray] = cheap ? CheapPath : FullPath;
        if (!_frozen && !outcome.Certain && cheap)
            CheapIntersections += outcome.Cost.QueriesConservative + outcome.Cost.ClassicalTests;
        if (outcome.Certain)
        {
            _done[ray] = true;
            return;
        }
        if (outcome.Primitive is not null)
        {
            if (!_frozen) _found[Stratum(ray)]++;
            if (_findEnds) _done[ray] = true;
            else (_trailing[ray], _machineTrailing[ray], _afterFind[ray]) = (1, 1, true);
        }
        else
        {
            _trailing[ray] *= _worstMiss(schedule);
            if (_machineWorstMiss is not null) _machineTrailing[ray] *= _machineWorstMiss(schedule);
        }
    }

    /// <summary>Marks <paramref name="ray"/>'s answer as certain: found by a classical test (a neighbour's occluder), never wrong.</summary>
    public void MarkCertain(int ray) => _done[ray] = true;

    /// <summary>
    /// Fixes each stratum's π from the searches so far (the pass's own rounds): later searches (budget rounds) only
    /// lower the rays' trailing W, they do not change how likely a ray was to have something left.
    /// </summary>
    public void Freeze()
    {
        if (_frozen) return;
        var priors = Priors(_trailing);
        for (var stratum = 0; stratum < _prior.Length; stratum++) _prior[stratum] = priors[stratum] ?? 0;
        if (_machineWorstMiss is not null)
        {
            var machine = Priors(_machineTrailing);
            for (var stratum = 0; stratum < _machinePrior.Length; stratum++) _machinePrior[stratum] = machine[stratum] ?? 0;
        }
        _frozen = true;
    }

    /// <summary>
    /// The share of lattice level <paramref name="level"/>'s cheap confirmations estimated to have something to find, from
    /// the searches so far; null before any (<see cref="CheapConfirmation"/> weighs it for the next finer level).
    /// </summary>
    public double? CheapPrior(int level) => CheapFirst + level < _prior.Length ? Priors(_trailing)[CheapFirst + level] : null;

    // Each stratum's π from its finds and open episodes (null when it has none), in one sweep over the rays: per stratum
    // its open rays, those with trailing misses and their trailing W summed in ray order.
    private double?[] Priors(double[] trailingOf)
    {
        var strata = _prior.Length;
        var (open, completed, trailing) = (new long[strata], new long[strata], new double[strata]);
        for (var i = 0; i < Rays; i++)
        {
            if (_path[i] == Unsearched || _done[i]) continue;
            var stratum = Stratum(i);
            open[stratum]++;
            if (trailingOf[i] >= 1) continue;
            completed[stratum]++;
            trailing[stratum] += trailingOf[i];
        }
        var priors = new double?[strata];
        for (var stratum = 0; stratum < strata; stratum++)
        {
            if (open[stratum] == 0) continue;
            var episodes = _found[stratum] + open[stratum];
            var w = completed[stratum] == 0 ? 0 : trailing[stratum] / completed[stratum];
            // Half a find and one episode more than seen (Jeffreys' prior on the find rate): a stratum whose searches found
            // nothing has not shown that its rays are right, only that few of them are wrong.
            priors[stratum] = Math.Min(PriorCap, (_found[stratum] + 0.5) / ((episodes + 1) * (1 - w)));
        }
        return priors;
    }

    private int Stratum(int ray) => (_path[ray], _afterFind[ray]) switch
    {
        (CheapPath, true) => CheapAfterFind,
        (CheapPath, false) => CheapFirst + (_levels?[ray] ?? 0),
        (_, true) => FullAfterFind,
        _ => FullFirst,
    };

    /// <summary>The probability ray <paramref name="ray"/> is wrong as the plan sees it (<see cref="Freeze"/> first).</summary>
    public double Expected(int ray) => Expected(ray, _prior, _trailing);

    private double Expected(int ray, double[] prior, double[] trailing)
    {
        if (!_frozen) throw new InvalidOperationException("freeze the ledger first");
        if (_path[ray] == Unsearched || _done[ray]) return 0;
        var (pi, w) = (prior[Stratum(ray)], trailing[ray]);
        return pi * w / (1 - pi + pi * w);
    }

    /// <summary>The expected wrong rays of the pass as the plan sees it.</summary>
    public double ExpectedTotal => Total(_prior, _trailing);

    /// <summary>The expected wrong rays of the pass on the machine the searches ran on.</summary>
    public double MachineExpectedTotal => Total(_machinePrior, _machineTrailing);

    private double Total(double[] prior, double[] trailing)
    {
        Freeze();
        var sum = 0.0;
        for (var i = 0; i < Rays; i++) sum += Expected(i, prior, trailing);
        return sum;
    }
}
