using QuantumRayTracing.Intersection;
using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Search;

/// <summary>
/// QSearch (Algorithm 1 of the ray tracing paper, after Boyer, Brassard, Høyer and Tapp) for one
/// search, as a state machine: <see cref="NextRequest"/> says which Grover run to do next and
/// <see cref="Observe"/> takes its measured index. A driver advances many of these in lock step so
/// that one engine call serves every active search (see <see cref="QSearchDriver"/>).
/// </summary>
/// <remarks>
/// Steps: sample the uniform superposition (r = 0) and test the index classically; then for each
/// bound M_l of the schedule draw r_l uniformly from 1..M_l, run Grover with r_l iterations, measure,
/// test. Stop at the first marked index or when the schedule is exhausted (not found).
/// </remarks>
public sealed class QSearch
{
    private readonly QSearchSchedule _schedule;
    private readonly SeededRandom _random;
    private int _stage; // 0: the initial sample; l ≥ 1: the run bounded by M_l
    private int _pendingIterations = -1;
    private Queue<int>? _planned; // only an engine that plans whole searches at once fills it

    private readonly OracleInput? _oracle;

    public QSearch(MarkedSet marked, QSearchSchedule schedule, SeededRandom random, OracleInput? oracle = null)
    {
        ArgumentNullException.ThrowIfNull(marked);
        ArgumentNullException.ThrowIfNull(schedule);
        if (schedule.Count != marked.Count)
            throw new ArgumentException($"schedule is for N = {schedule.Count}, search has N = {marked.Count}", nameof(schedule));
        Marked = marked;
        _schedule = schedule;
        _random = random;
        _oracle = oracle;
        if (schedule.IsFixed) _stage = 1;
    }

    public MarkedSet Marked { get; }

    public bool IsDone { get; private set; }

    /// <summary>The marked index found, or null while running or when the search ended without one.</summary>
    public int? Found { get; private set; }

    /// <summary>The last measured index (Algorithm 1 returns it with found = false on a miss).</summary>
    public int LastMeasured { get; private set; } = -1;

    public SearchCost Cost { get; private set; }

    public GroverRequest NextRequest()
    {
        if (IsDone) throw new InvalidOperationException("the search has ended");
        if (_pendingIterations < 0)
            _pendingIterations = _planned is { Count: > 0 } ? _planned.Dequeue() : DrawIterations(_stage);
        return new GroverRequest(Marked, _pendingIterations, _oracle);
    }

    /// <summary>
    /// Every Grover run the search may still do, in order: the iteration counts of all remaining stages
    /// are drawn now, and <see cref="NextRequest"/> returns them one by one. An engine can then run the
    /// whole rest of the search in one call; the runs after the first marked index are never observed.
    /// </summary>
    /// <remarks>The draws are the same uniform choices as stage by stage, taken earlier: the algorithm and its
    /// counts are unchanged, only the order in which a shared generator serves several searches differs.</remarks>
    public IReadOnlyList<GroverRequest> PlanRemaining()
    {
        if (IsDone) throw new InvalidOperationException("the search has ended");
        var runs = new List<GroverRequest> { NextRequest() };
        _planned ??= new Queue<int>();
        for (var stage = _stage + 1 + _planned.Count; stage <= _schedule.Bounds.Count; stage++)
            _planned.Enqueue(DrawIterations(stage));
        runs.AddRange(_planned.Select(r => new GroverRequest(Marked, r, _oracle)));
        return runs;
    }

    private int DrawIterations(int stage) =>
        stage == 0 ? 0
        : _schedule.IsFixed ? _schedule.Bounds[stage - 1]
        : _random.NextInt(1, _schedule.Bounds[stage - 1]);

    /// <summary>
    /// Takes the measured index of the pending run. A noisy machine can read an index in N..2^n − 1 (n
    /// index qubits): it names no primitive, so it is a miss that needs no classical test.
    /// </summary>
    public void Observe(int measured)
    {
        if (_pendingIterations < 0) throw new InvalidOperationException("no Grover run is pending");
        var readable = 1 << SearchRegisters.For(Marked.Count).IndexQubits;
        if (measured < 0 || measured >= readable)
            throw new ArgumentOutOfRangeException(nameof(measured), measured, $"measured index outside 0..{readable - 1}");
        var inRange = measured < Marked.Count;
        Cost += SearchCost.OfGroverRun(_pendingIterations) + (inRange ? SearchCost.OfClassicalTest : default);
        _pendingIterations = -1;
        LastMeasured = measured;
        if (inRange && Marked.Contains(measured))
        {
            Found = measured;
            IsDone = true;
        }
        else if (++_stage > _schedule.Bounds.Count)
        {
            IsDone = true;
        }
    }
}
