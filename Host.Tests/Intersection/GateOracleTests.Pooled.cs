using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Tests.Intersection;

/// <summary>
/// The pooled query (one QSearch query over many rays' (ray, primitive) pairs) against the pooled round's own pair test:
/// a pair is marked exactly when its ray's table marks the primitive under its window (<see cref="RayTable.Marked"/>, what
/// the analytic engine's pooled search marks), on every basis state of small pools.
/// </summary>
public partial class GateOracleTests
{
    private const string PooledCheckOperation = "QuantumRayTracing.Intersection.CheckPooledQueryOnEveryPair";

    /// <summary>Mixed's first four primitives: a pool of 3 rays x 4 primitives fills no power of two in rays.</summary>
    private static readonly Lazy<SceneGeometry> FourScene = new(() =>
    {
        var scene = SceneLoader.Parse(Mixed, "mixed");
        return new SceneGeometry(scene with { Primitives = scene.Primitives.Take(4).ToList() });
    });

    [Theory]
    [InlineData("baseline")]
    [InlineData("compact")]
    [InlineData("narrow")]
    [InlineData("device")]
    public void PooledQueryMarksExactlyThePairsItsRaysTablesAccept(string construction)
    {
        var random = new SeededRandom(20261129);
        // Pools mixing windows (full range, random range, both tie-breaks, a near cut) and rays of different depth bits:
        // 3 rays x 4 primitives, 3 x 5 (neither a power of two), 2 x 7 on the fixed-point grid and the stack's 2 x 6.
        var pools = new List<OracleCase[]>
        {
            Pool(RandomCases("four", FourScene.Value, random, rays: 3), [0, 7, 13]),
            Pool(RandomCases("mixed", MixedScene.Value, random, rays: 3), [2, 8, 14]),
            Pool(RandomCases("fixed-point", FixedPointScene.Value, random, rays: 2), [3, 9]),
            Pool([.. StackCases()], [0, 3]),
        };
        pools = pools.Select(pool => pool.Select(c => c with { Input = c.Input with { Construction = Construction(construction) } }).ToArray()).ToList();
        var expected = pools.Select(pool => pool.Select(c => PairTest(c.Input)).ToArray()).ToList();
        // Negative control: the first pool again, one pair's expected answer flipped; the check must reject it.
        var flipped = expected[0].Select(ray => ray.ToArray()).ToArray();
        flipped[1][2] = !flipped[1][2];
        var held = CheckPools([.. pools, pools[0]], [.. expected, flipped]);
        for (var k = 0; k < pools.Count; k++)
            Assert.True(held[k], $"{construction}, pool {k} ({string.Join("; ", pools[k].Select(c => c.Name))}): the pooled query differs from the pair test on some pair, or leaves a register or phase behind");
        Assert.False(held[^1], $"{construction}: the check accepted a pool with one pair's answer flipped");
        var marks = expected.SelectMany(pool => pool.SelectMany(ray => ray)).ToArray();
        Assert.True(marks.Count(m => m) >= 8 && marks.Count(m => !m) >= 8, $"{marks.Count(m => m)} marked and {marks.Count(m => !m)} unmarked pairs");
    }

    /// <summary>The cases at <paramref name="picks"/>, one pool.</summary>
    private static OracleCase[] Pool(IReadOnlyList<OracleCase> cases, int[] picks) => [.. picks.Select(k => cases[k])];

    /// <summary>The pooled round's pair test for one ray: its compact table's marked rows under its window.</summary>
    private static bool[] PairTest(OracleInput input)
    {
        var marked = RayTable.BuildCompact(input.Geometry, input.Table.Ray).Marked(input.Window);
        return [.. Enumerable.Range(0, input.Table.Count).Select(marked.Contains)];
    }

    /// <summary>Checks the pooled query on every pair of each pool against <paramref name="expected"/>, one simulator call per pool over both bridges.</summary>
    private bool[] CheckPools(IReadOnlyList<OracleCase[]> pools, IReadOnlyList<bool[][]> expected)
    {
        static string Bools(IEnumerable<bool> values) => "[" + string.Join(", ", values.Select(v => v ? "true" : "false")) + "]";
        var results = new bool[pools.Count];
        fixture.Engine.Pool.ForEach([.. Enumerable.Range(0, pools.Count)], (k, bridge) =>
        {
            var input = GateEngine.PooledArgument([.. pools[k].Select(c => c.Input)]);
            var outputs = "[" + string.Join(", ", expected[k].Select(Bools)) + "]";
            results[k] = bridge.Run($"{PooledCheckOperation}([{input}], [{outputs}])")[0] == "[true]";
        });
        return results;
    }
}
