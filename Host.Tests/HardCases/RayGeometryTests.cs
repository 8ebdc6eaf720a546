using System.Text.RegularExpressions;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Engines;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.HardCases;

/// <summary>
/// Rays that graze the geometry, on every engine: parallel to a primitive's plane or lying in it, through a
/// shared edge or a corner of four tiles (also where the floating-point point lands 1e-15 below the grid line),
/// starting on a surface, and meeting two primitives at the same depth.
/// </summary>
/// <remarks>
/// The rules, from <see cref="SceneGeometry"/> and <see cref="RayTable"/>: a rectangle holds the half-open cells
/// [min, max) on its in-plane axes, so of tiles sharing an edge or a corner only the one whose min edge it is claims
/// the point; points are floored after a 1e-9 snap, so a point a rounding error below a grid line lands on it; a ray
/// parallel to a plane (|direction along its normal| &lt; 1e-12) never meets it; a plane must lie more than 1e-9 ahead in
/// t, so a ray leaving a surface does not hit that surface (nor one coplanar with it) at t = 0; the closest hit is the
/// smallest (depth, id), so of two primitives at the same depth the smaller id wins under the strict tie-break, and
/// either may under the random one.
/// </remarks>
[Collection(QSharpCollection.Name)]
public partial class RayGeometryTests(FullStateFixture fixture)
{
    // 4-bit integer grid. Four tiles in the plane z = 8 meeting at (6, 6); two coplanar full planes at z = 12 (ids 4 and 6,
    // equal depth for every ray that reaches them); a wall in the plane x = 12. N = 7, not a power of two.
    private static readonly SceneGeometry Geometry = new(With(4, 0,
        Rect(2, 2, 8, 6, 6, 8),     // 0: tile A, [2, 6) x [2, 6)
        Rect(6, 2, 8, 10, 6, 8),    // 1: tile B, [6, 10) x [2, 6)
        Rect(2, 6, 8, 6, 10, 8),    // 2: tile C, [2, 6) x [6, 10)
        Rect(6, 6, 8, 10, 10, 8),   // 3: tile D, [6, 10) x [6, 10)
        Rect(0, 0, 12, 15, 15, 12), // 4: back plane
        Rect(12, 0, 0, 12, 15, 15), // 5: wall x = 12
        Rect(0, 0, 12, 15, 15, 12)));  // 6: the back plane again, coplanar with 4

    private static readonly Vec3 Up = new(0, 0, 1);

    /// <summary>A ray, the closest hit under the strict order (null: none), and every primitive the random tie-break may end on.</summary>
    public sealed record RayCase(string Name, Ray Ray, int? Strict, int[] Random)
    {
        public override string ToString() => Name;
    }

    private static RayCase Case(string name, Ray ray, int? strict) =>
        new(name, ray, strict, strict == 4 ? [4, 6] : strict is { } p ? [p] : []);

    public static readonly RayCase[] Cases =
    [
        Case("inside tile A", new(new Vec3(3.5, 3.5, 0), Up), 0),
        Case("A's min corner (2, 2)", new(new Vec3(2, 2, 0), Up), 0),
        Case("edge x = 6 shared by A and B: B's min edge", new(new Vec3(6, 4.5, 0), Up), 1),
        Case("edge y = 6 shared by A and C: C's min edge", new(new Vec3(3, 6, 0), Up), 2),
        Case("corner (6, 6) of all four tiles: D's min corner", new(new Vec3(6, 6, 0), Up), 3),
        Case("D's max edge x = 10: past the tiles to the back planes", new(new Vec3(10, 7, 0), Up), 4),
        Case("D's max corner (10, 10)", new(new Vec3(10, 10, 0), Up), 4),
        // From z = 0.5 with direction z 0.75 the plane z = 8 is at t = 10, where x = 0.1 + 10 · 0.59 evaluates to
        // 5.999999999999999: the snap puts it on the edge x = 6, B's side.
        Case("slanted onto the edge x = 6, 1e-15 below it", new(new Vec3(0.1, 4.5, 0.5), new Vec3(0.59, 0, 0.75)), 1),
        Case("slanted onto the corner (6, 6), 1e-15 below it", new(new Vec3(0.1, 0.1, 0.5), new Vec3(0.59, 0.59, 0.75)), 3),
        Case("parallel to the tiles and back planes: the wall", new(new Vec3(3.5, 3.5, 5), new Vec3(1, 0, 0)), 5),
        Case("lying in the tiles' plane: the wall", new(new Vec3(0.5, 4.5, 8), new Vec3(1, 0, 0)), 5),
        Case("parallel to every plane: nothing", new(new Vec3(13, 4, 4), new Vec3(0, 1, 0)), null),
        Case("leaving A upwards: not A, the back planes", new(new Vec3(3.5, 3.5, 8), Up), 4),
        Case("leaving A downwards: nothing", new(new Vec3(3.5, 3.5, 8), new Vec3(0, 0, -1)), null),
        Case("leaving A from 1e-12 below it (within the snap): not A", new(new Vec3(3.5, 3.5, 8 - 1e-12), Up), 4),
        Case("leaving the coplanar back planes downwards: neither, A", new(new Vec3(3.5, 3.5, 12), new Vec3(0.25, 0, -1)), 0),
        Case("leaving back plane 4 as a secondary ray: not 6 at t = 0 either", new(new Vec3(3.5, 3.5, 12), new Vec3(0.25, 0, -1), ExcludedPrimitive: 4), 0),
        Case("leaving A as a secondary ray", new(new Vec3(3.5, 3.5, 8), new Vec3(0.1, 0.2, 1), ExcludedPrimitive: 0), 4),
        Case("running along the wall: parallel to it, up to the back planes", new(new Vec3(12, 4, 4), Up), 4),
    ];

    public static TheoryData<string> Engines => new(HardCaseEngines.Classical, HardCaseEngines.Randomized, HardCaseEngines.Analytic, HardCaseEngines.FullState, HardCaseEngines.Gate);

    private static RayTable TableOf(RayCase c) => RayTable.Build(Geometry, c.Ray);

    [Fact]
    public void TablesHoldTheDocumentedRulesAndNoNaN()
    {
        foreach (var c in Cases)
        {
            var table = TableOf(c);
            for (var p = 0; p < table.Count; p++)
            {
                Assert.True(double.IsFinite(table.Distance(p)), $"{c}: row {p} distance {table.Distance(p)}");
                Assert.True(table.Depth(p) >= 0, $"{c}: row {p} depth {table.Depth(p)}");
            }
            // The hand-derived answer, the brute force over the rows and the classical search agree.
            Assert.True(c.Strict == BruteForceClosest(table), $"{c}: expected {c.Strict}, brute force {BruteForceClosest(table)}");
        }
        // Parallel rows are invalid, not NaN or infinite: the ray along x meets only the wall; the one along y nothing.
        var alongX = TableOf(Cases.Single(c => c.Name.StartsWith("parallel to the tiles")));
        Assert.Equal([5], Enumerable.Range(0, 7).Where(alongX.IsValid));
        var alongY = TableOf(Cases.Single(c => c.Name.StartsWith("parallel to every")));
        Assert.DoesNotContain(Enumerable.Range(0, 7), alongY.IsValid);
        // On the snapped edge the point is x = 6 exactly (floor alone would give 5, A's cell).
        var slanted = TableOf(Cases.Single(c => c.Name.StartsWith("slanted onto the edge")));
        Assert.True(0.1 + 10 * 0.59 < 6);
        Assert.Equal(6, slanted.Point(1, 0));
        // The origin's own plane (t = 0, or t = 1e-12 within the snap) gives no row.
        Assert.False(TableOf(Cases.Single(c => c.Name.StartsWith("leaving A upwards"))).IsValid(0));
        Assert.False(TableOf(Cases.Single(c => c.Name.StartsWith("leaving A from 1e-12"))).IsValid(0));
        var fromBack = TableOf(Cases.Single(c => c.Name.StartsWith("leaving the coplanar")));
        Assert.False(fromBack.IsValid(4) || fromBack.IsValid(6));
    }

    private static bool Simulated(string engine) => engine is HardCaseEngines.FullState or HardCaseEngines.Gate;

    /// <summary>
    /// The rays the simulated engines trace (a call costs them ~70 ms and a gate-level run ~10 ms more): an edge, a corner,
    /// a snapped edge, a ray in a plane, one leaving a surface, a tie and a miss. The others differ from these only in the
    /// table, which the gate oracle's check below covers row by row.
    /// </summary>
    private static readonly string[] SimulatedRays =
    [
        "edge x = 6 shared by A and B: B's min edge", "corner (6, 6) of all four tiles: D's min corner", "slanted onto the edge x = 6, 1e-15 below it",
        "lying in the tiles' plane: the wall", "leaving A upwards: not A, the back planes", "D's max corner (10, 10)", "parallel to every plane: nothing",
    ];

    /// <summary>TracePass on an engine, with enough rounds to reach the best hit (bounds in the comments).</summary>
    private Hit?[] Trace(string engine, IReadOnlyList<Ray> rays, TieBreak tieBreak)
    {
        // Classical: 1 round (certain). Randomized: 60 rounds of 2 of the 7 primitives: the best is left untested in every
        // round with probability (5/7)^60 < 2e-9 (and the seed is fixed). Analytic: QSearch's own schedule, which misses
        // with probability at most 0.152 when t ≥ 1 of N = 7 are accepted (QSearchExpectations.FalseNegative, t = 2);
        // a ray here needs at most 3 finds (6 → 4 → 0), so 16 rounds fall short (fewer than 3 successes of
        // Binomial(16, 0.848)) with probability below 4e-10 per ray. The simulated engines run one Grover run with r = 1 per round (one call
        // per round, not three), which misses with probability at most 0.291 for the t ≤ 3 their rays have
        // (1 − sin²(3θ), sin²θ = 3/7): 24 rounds fall short of 3 finds with probability below 3e-10 per ray, and the
        // random tie-break, which needs one find among t ≥ 2, within 6 rounds with probability below 0.015^6.
        var (rounds, schedule) = engine switch
        {
            HardCaseEngines.Classical => (1, null),
            HardCaseEngines.Randomized => (60, null),
            HardCaseEngines.Analytic => (16, null),
            _ => (tieBreak == TieBreak.Strict ? 24 : 6, QSearchSchedule.Fixed(Geometry.Count, [1])),
        };
        using var search = HardCaseEngines.Search(engine, fixture, seed: 13);
        return TracePass.Run("primary", search, Geometry, rays, new PassOptions(rounds, tieBreak, Schedule: schedule)).Hits;
    }

    [Theory]
    [MemberData(nameof(Engines))]
    public void StrictClosestHitIsTheSameOnEveryEngine(string engine)
    {
        var cases = Simulated(engine) ? Cases.Where(c => SimulatedRays.Contains(c.Name)).ToArray() : Cases;
        Assert.True(cases.Length >= SimulatedRays.Length);
        var hits = Trace(engine, cases.Select(c => c.Ray).ToArray(), TieBreak.Strict);
        for (var k = 0; k < cases.Length; k++)
        {
            Assert.True(cases[k].Strict == hits[k]?.Primitive, $"{engine}, {cases[k]}: expected {cases[k].Strict}, got {hits[k]?.Primitive}");
            if (hits[k] is { } hit)
                Assert.True(double.IsFinite(hit.Point.X) && double.IsFinite(hit.Point.Y) && double.IsFinite(hit.Point.Z), $"{engine}, {cases[k]}: point {hit.Point}");
        }
    }

    [Theory]
    [MemberData(nameof(Engines))]
    public void RandomTieBreakEndsOnEitherOfEqualDepths(string engine)
    {
        // Only the rays whose answer the tie-break can change: those ending on the coplanar back planes.
        var ties = Cases.Where(c => c.Random.Length > 1).ToArray();
        var hits = Trace(engine, ties.Select(c => c.Ray).ToArray(), TieBreak.Random);
        for (var k = 0; k < ties.Length; k++)
            Assert.True(hits[k] is { } h && ties[k].Random.Contains(h.Primitive), $"{engine}, {ties[k]}: got {hits[k]?.Primitive}, expected one of [{string.Join(", ", ties[k].Random)}]");
    }

    [Fact]
    public void GateOracleMarksExactlyWhatVerifyRpcAccepts()
    {
        // Every ray with three windows (its full range, and closer than its strict answer under each tie-break), on
        // every basis state, with the default construction (GateOracleTests checks that the others mark the same rows).
        var inputs = new List<(string Name, OracleInput Input)>();
        var construction = OracleConstruction.Default;
            foreach (var c in Cases)
            {
                var table = TableOf(c);
                var windows = new List<(string, HitWindow)> { ("full range", table.FullRange) };
                if (c.Strict is { } best)
                {
                    windows.Add(("closer, strict", HitWindow.Closer(0, table.Depth(best), best, TieBreak.Strict)));
                    windows.Add(("closer, random", HitWindow.Closer(0, table.Depth(best), best, TieBreak.Random)));
                }
                foreach (var (what, window) in windows)
                    inputs.Add(($"{c}, {what}, {construction.Name}", new OracleInput(table, window) { Construction = construction }));
            }
        // Half the inputs on each bridge.
        var halves = new[] { inputs.Take(inputs.Count / 2).ToArray(), inputs.Skip(inputs.Count / 2).ToArray() };
        var results = new bool[2][];
        fixture.Engine.Pool.ForEach([0, 1], (h, bridge) =>
        {
            var expression = $"QuantumRayTracing.Intersection.EvaluateIntersectionOracleOnEveryRow([{string.Join(", ", halves[h].Select(i => GateEngine.OracleArgument(i.Input)))}])";
            results[h] = RowOutput().Matches(bridge.Run(expression)[0]).Select(m => m.Groups[1].Value == "true").ToArray();
        });
        var outputs = results[0].Concat(results[1]).ToArray();
        Assert.Equal(inputs.Count * Geometry.Count, outputs.Length);
        var marked = 0;
        for (var k = 0; k < inputs.Count; k++)
        {
            var (table, window) = (inputs[k].Input.Table, inputs[k].Input.Window);
            for (var p = 0; p < Geometry.Count; p++)
            {
                var expected = table.Verify(p, window);
                Assert.True(outputs[k * Geometry.Count + p] == expected, $"{inputs[k].Name}, row {p}: gate oracle {!expected}, verify-rpc {expected}");
                if (expected) marked++;
            }
        }
        Assert.True(marked > 0);
    }

    /// <summary>The output of one row of the Q# result: <c>(true, [3, 0, 0, 0, 0, 0, 0])</c>.</summary>
    [GeneratedRegex(@"\((true|false), \[[0-9, ]+\]\)")]
    private static partial Regex RowOutput();
}
