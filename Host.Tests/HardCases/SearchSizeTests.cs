using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Engines;
using QuantumRayTracing.Tests.Search;
using QuantumRayTracing.Tests.Statistics;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.HardCases;

/// <summary>
/// Search sizes and marked counts at their extremes on every quantum engine: t = 0, t = 1, t > N/2, t = N;
/// N = 1 and N that are not powers of two (3, 5, 7, 100). Each case is a ray's table, so the same request
/// serves the analytic and full-state engines (which read its marked set) and the gate engine (which
/// computes the marked set with its circuit from the same table).
/// </summary>
/// <remarks>
/// Exact where the outcome is certain (t = 0: nothing found, every run of the schedule made; t = N: found
/// at the first sample). Elsewhere statistical: the analytic engine seeded, the Q# engines not (the simulator
/// cannot be seeded), every check with false-failure probability <see cref="StatisticalBounds.FalseFailure"/>.
/// Each success-rate check first asserts that its acceptance interval excludes the unamplified rate t/N, so
/// an engine that skipped or botched the Grover iterations would fail it. Each engine gets every case in one
/// batch (one engine call, or one per QSearch round), as a pass would send them; a Q# test makes at most 18
/// statistical checks, within the 20 that <see cref="StatisticalBounds.FalseFailure"/> budgets for.
/// </remarks>
[Collection(QSharpCollection.Name)]
public class SearchSizeTests(FullStateFixture fixture)
{
    // Every ray runs from (3.5, 3.5, 0) along +z. A marked primitive is a plane spanning x, y in [0, 8), which the
    // ray meets at (3, 3, z); an unmarked one spans [10, 12), which it misses. Depths 1..14 repeat past N = 14.
    private static readonly Ray Up = new(new Vec3(3.5, 3.5, 0), new Vec3(0, 0, 1));

    /// <summary>N primitives of which <paramref name="marked"/> are hit; the table of <see cref="Up"/> through them.</summary>
    private static RayTable Layered(int count, IReadOnlyCollection<int> marked) =>
        Table(With(4, 0, Enumerable.Range(0, count).Select(p =>
        {
            var z = 1 + p % 14;
            return marked.Contains(p) ? Rect(0, 0, z, 8, 8, z) : Rect(10, 10, z, 12, 12, z);
        })), Up);

    /// <summary>One Grover request over a ray's table: N, the marked ids and r.</summary>
    public sealed record SizeCase(int Count, int[] Marked, int Iterations, string Why, bool Gate = false, bool FullState = true)
    {
        private readonly Lazy<RayTable> _table = new(() => Layered(Count, Marked));

        public RayTable Table => _table.Value;

        public override string ToString() => $"N={Count} t={Marked.Length} r={Iterations} ({Why})";
    }

    private static int[] Ids(int count, Func<int, bool> marked) => Enumerable.Range(0, count).Where(marked).ToArray();

    private static readonly SizeCase[] GroverCases =
    [
        new(1, [], 2, "N = 1, t = 0", Gate: true),
        new(1, [0], 1, "N = 1, t = N", Gate: true),
        new(3, [], 1, "t = 0"),
        new(3, [2], 1, "t = 1, last index", Gate: true),
        new(3, [0, 2], 1, "t > N/2", Gate: true),
        new(3, [0, 1, 2], 2, "t = N"),
        new(5, [0, 1, 3, 4], 1, "t > N/2"),
        new(7, [6], 2, "t = 1, last index", Gate: true),
        new(7, [0, 1, 2, 4, 5], 1, "t > N/2", Gate: true),
        new(7, Ids(7, _ => true), 1, "t = N", Gate: true),
        new(100, [99], 7, "t = 1, last index, optimal r"),
        new(100, [], 3, "t = 0"),
        new(100, Ids(100, p => p % 5 < 3), 1, "t = 60 > N/2"),
        new(100, Ids(100, _ => true), 2, "t = N"),
    ];

    private static readonly SizeCase[] SearchCases =
    [
        new(1, [], 0, "N = 1, t = 0", Gate: true),
        new(1, [0], 0, "N = 1, t = N", Gate: true),
        new(3, [], 0, "t = 0", Gate: true),
        new(3, [1], 0, "t = 1"),
        new(3, [0, 2], 0, "t > N/2"),
        new(5, [0, 1, 2, 4], 0, "t > N/2"),
        new(7, [3], 0, "t = 1", Gate: true),
        new(7, [0, 1, 3, 5, 6], 0, "t > N/2"),
        new(7, Ids(7, _ => true), 0, "t = N", Gate: true),
        // Every search runs the whole schedule, up to r = 10 at N = 100: too slow to simulate 100 times; fullstate
        // checks the t = 0 rule at N = 1 and 3.
        new(100, [], 0, "t = 0", FullState: false),
        new(100, [42], 0, "t = 1"),
        new(100, Ids(100, p => p % 5 < 3), 0, "t = 60 > N/2"),
        new(100, Ids(100, _ => true), 0, "t = N"),
    ];

    // The gate engine simulates every row in every lookup, about 10 ms a run even at N = 1, so it runs only the
    // cases marked for it (N ≤ 7: the certain ones and those where amplification moves the success rate most).
    private static bool Runs(string engine, SizeCase c) => engine switch
    {
        HardCaseEngines.Gate => c.Gate,
        HardCaseEngines.FullState => c.FullState,
        _ => true,
    };

    public static TheoryData<string> Engines => new(HardCaseEngines.Analytic, HardCaseEngines.FullState, HardCaseEngines.Gate);

    /// <summary>sin²((2r+1)θ), sin²θ = t/N, written out here rather than taken from the code under test.</summary>
    private static double ClosedForm(int count, int marked, int iterations)
    {
        if (marked == 0 || marked == count) return marked == 0 ? 0 : 1;
        var theta = Math.Asin(Math.Sqrt((double)marked / count));
        return Math.Pow(Math.Sin((2 * iterations + 1) * theta), 2);
    }

    [Theory]
    [MemberData(nameof(Engines))]
    public void GroverOutcomesStayBelowNAndSucceedAtTheClosedFormRate(string engineName)
    {
        var shots = engineName switch { HardCaseEngines.Analytic => 20_000, HardCaseEngines.FullState => 300, _ => 60 };
        var cases = GroverCases.Where(c => Runs(engineName, c)).ToArray();
        var requests = cases.Select(c =>
        {
            var marked = c.Table.Marked(c.Table.FullRange);
            Assert.Equal(c.Marked, marked.Indices.ToArray());
            return new GroverRequest(marked, c.Iterations, new OracleInput(c.Table, c.Table.FullRange));
        }).ToArray();
        // One batch for every case, as a pass sends it.
        using var engine = HardCaseEngines.Grover(engineName, fixture, seed: 5);
        var measured = engine.Measure(requests.SelectMany(r => Enumerable.Repeat(r, shots)).ToArray());
        Assert.Equal(cases.Length * shots, measured.Count);
        for (var k = 0; k < cases.Length; k++)
            CheckGroverCase(engineName, cases[k], requests[k].Marked, measured.Skip(k * shots).Take(shots).ToArray());
    }

    private static void CheckGroverCase(string engineName, SizeCase c, MarkedSet marked, int[] outcomes)
    {
        var shots = outcomes.Length;
        var what = $"{engineName}, {c}";
        Assert.All(outcomes, o => Assert.True(o >= 0 && o < c.Count, $"{what}: outcome {o} outside 0..{c.Count - 1}"));
        var hits = outcomes.Count(marked.Contains);
        if (c.Marked.Length == 0 || c.Marked.Length == c.Count)
        {
            // Certain: no outcome can be marked, or every one is.
            Assert.True(hits == (c.Marked.Length == 0 ? 0 : shots), $"{what}: {hits} of {shots} outcomes marked");
            return;
        }
        var p = ClosedForm(c.Count, c.Marked.Length, c.Iterations);
        var (low, high) = StatisticalBounds.BinomialInterval(p, shots);
        var unamplified = (double)c.Marked.Length / c.Count * shots;
        Assert.True(unamplified < low || unamplified > high, $"{what}: the check cannot tell p = {p:0.####} from t/N");
        StatisticalBounds.AssertBinomial(hits, p, shots, what);
        // Uniform within the marked and within the unmarked indices, when every cell expects enough counts for the test.
        var distribution = Enumerable.Range(0, c.Count)
            .Select(i => marked.Contains(i) ? p / c.Marked.Length : (1 - p) / (c.Count - c.Marked.Length)).ToArray();
        if (distribution.Min() * shots >= 5)
            StatisticalBounds.AssertFits(StatisticalBounds.Histogram(outcomes, c.Count), distribution, what);
    }

    [Theory]
    [MemberData(nameof(Engines))]
    public void QSearchFindsOnlyMarkedIndicesAndEndsByItsRule(string engineName)
    {
        var searches = engineName switch { HardCaseEngines.Analytic => 20_000, HardCaseEngines.FullState => 120, _ => 30 };
        var cases = SearchCases.Where(c => Runs(engineName, c)).ToArray();
        foreach (var c in cases) Assert.Equal(c.Marked, c.Table.Marked(c.Table.FullRange).Indices.ToArray());
        // Every case's searches in one run, advancing in lock step: one engine call per round.
        using var search = HardCaseEngines.Search(engineName, fixture, seed: 9);
        var outcomes = search.Run(cases.SelectMany(c => Enumerable.Repeat(new HitQuery(c.Table, c.Table.FullRange), searches)).ToArray());
        for (var k = 0; k < cases.Length; k++)
            CheckSearchCase(engineName, cases[k], outcomes.Skip(k * searches).Take(searches).ToArray());
    }

    private static void CheckSearchCase(string engineName, SizeCase c, HitOutcome[] outcomes)
    {
        var what = $"{engineName}, {c}";
        var schedule = new QSearchSchedule(c.Count);
        Assert.All(outcomes, o => Assert.True(o.Primitive is null || c.Marked.Contains(o.Primitive.Value), $"{what}: found unmarked {o.Primitive}"));
        Assert.All(outcomes, o => Assert.InRange(o.Cost.GroverRuns, 1, schedule.Bounds.Count + 1));
        if (c.Marked.Length == 0)
        {
            // Not found, after the initial sample and one run per bound M_l: the whole schedule.
            Assert.All(outcomes, o => Assert.Null(o.Primitive));
            Assert.All(outcomes, o => Assert.Equal(schedule.Bounds.Count + 1, o.Cost.GroverRuns));
            return;
        }
        if (c.Marked.Length == c.Count)
        {
            // Every index is a hit: the initial sample finds one, at no query and one classical test.
            Assert.All(outcomes, o => Assert.Equal(new SearchCost(0, 0, 1, 1), o.Cost));
            Assert.All(outcomes, o => Assert.NotNull(o.Primitive));
            return;
        }
        var misses = outcomes.Count(o => o.Primitive is null);
        StatisticalBounds.AssertBinomial(misses, QSearchExpectations.FalseNegative(c.Count, c.Marked.Length, schedule), outcomes.Length, $"{what}: misses");
        // A miss is reported only after the whole schedule ran.
        Assert.All(outcomes.Where(o => o.Primitive is null), o => Assert.Equal(schedule.Bounds.Count + 1, o.Cost.GroverRuns));
    }
}
