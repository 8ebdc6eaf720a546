using System.Text.RegularExpressions;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Engines;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Intersection;

/// <summary>
/// The gate-level intersection oracle against the classical verify-rpc, on every basis state of many
/// rays and windows, and the gate engine's Grover runs against the closed form. The Grover checks are
/// statistical (the simulator cannot be seeded), each with false-failure probability
/// <see cref="StatisticalBounds.FalseFailure"/>.
/// </summary>
[Collection(QSharpCollection.Name)]
public partial class GateOracleTests(FullStateFixture fixture)
{
    private const string EvaluateOperation = "QuantumRayTracing.Intersection.EvaluateIntersectionOracleOnEveryRow";
    private const string CheckOperation = "QuantumRayTracing.Intersection.CheckIntersectionOracleOnEveryRow";

    /// <summary>Five primitives (not a power of two) on a 4-bit integer grid: planes on every axis, overlapping in depth.</summary>
    private const string Mixed = """
        {
          "image": { "width": 4, "height": 4 },
          "grid": { "integerBits": 4, "fractionBits": 0 },
          "camera": { "position": [8, 8, 0], "lookAt": [8, 8, 15] },
          "materials": { "white": { "diffuse": [0.8, 0.8, 0.8] } },
          "rectangles": [
            { "min": [2, 2, 4], "max": [12, 12, 4], "material": "white" },
            { "min": [4, 1, 7], "max": [14, 10, 7], "material": "white" },
            { "min": [0, 0, 10], "max": [15, 15, 10], "material": "white" },
            { "min": [3, 5, 2], "max": [3, 13, 13], "material": "white" },
            { "min": [0, 1, 0], "max": [15, 1, 15], "material": "white" }
          ]
        }
        """;

    /// <summary>Seven primitives on a 3.2 fixed-point grid (steps of 0.25), bounds off the integers.</summary>
    private const string FixedPoint = """
        {
          "image": { "width": 4, "height": 4 },
          "grid": { "integerBits": 3, "fractionBits": 2 },
          "camera": { "position": [4, 4, 0], "lookAt": [4, 4, 7] },
          "materials": { "white": { "diffuse": [0.8, 0.8, 0.8] } },
          "rectangles": [
            { "min": [0.75, 1.25, 2.5], "max": [5.5, 6.25, 2.5], "material": "white" },
            { "min": [2.25, 0.5, 4.75], "max": [7.75, 3.5, 4.75], "material": "white" },
            { "min": [0, 0, 6.25], "max": [7.75, 7.75, 6.25], "material": "white" },
            { "min": [3.5, 0.25, 0.5], "max": [3.5, 7.25, 6], "material": "white" },
            { "min": [0.5, 2.75, 1], "max": [6.5, 2.75, 7.5], "material": "white" },
            { "min": [1.25, 4.5, 3.75], "max": [2.75, 5.75, 3.75], "material": "white" },
            { "min": [5.25, 1, 1.75], "max": [5.25, 6.5, 5.25], "material": "white" }
          ]
        }
        """;

    /// <summary>Six full parallel planes: a ray along +z through them hits every one.</summary>
    private const string Stack = """
        {
          "image": { "width": 4, "height": 4 },
          "grid": { "integerBits": 4, "fractionBits": 0 },
          "camera": { "position": [7.5, 7.5, 0], "lookAt": [7.5, 7.5, 15] },
          "materials": { "white": { "diffuse": [0.8, 0.8, 0.8] } },
          "rectangles": [
            { "min": [0, 0, 2], "max": [15, 15, 2], "material": "white" },
            { "min": [0, 0, 4], "max": [15, 15, 4], "material": "white" },
            { "min": [0, 0, 6], "max": [15, 15, 6], "material": "white" },
            { "min": [0, 0, 8], "max": [15, 15, 8], "material": "white" },
            { "min": [0, 0, 10], "max": [15, 15, 10], "material": "white" },
            { "min": [0, 0, 12], "max": [15, 15, 12], "material": "white" }
          ]
        }
        """;

    private static readonly Lazy<SceneGeometry> MixedScene = new(() => new SceneGeometry(SceneLoader.Parse(Mixed, "mixed")));
    private static readonly Lazy<SceneGeometry> FixedPointScene = new(() => new SceneGeometry(SceneLoader.Parse(FixedPoint, "fixed-point")));
    private static readonly Lazy<SceneGeometry> StackScene = new(() => new SceneGeometry(SceneLoader.Parse(Stack, "stack")));
    private static readonly Lazy<SceneGeometry> QornellScene =
        new(() => new SceneGeometry(SceneLoader.Load(Path.Combine(RepositoryPaths.Scenes, "qornell-8.json"))));

    /// <summary>One oracle input and where it came from, for failure messages.</summary>
    private sealed record OracleCase(string Name, OracleInput Input)
    {
        public override string ToString() => Name;
    }

    /// <summary>A gate engine on the fixture's bridges; the fixture owns and stops them.</summary>
    private GateEngine Engine => new(fixture.Engine.Pool);

    [Theory]
    [InlineData("baseline")]
    [InlineData("compact")]
    [InlineData("narrow")]
    [InlineData("device")]
    public void OracleMatchesVerifyRpcOnEveryBasisState(string construction)
    {
        // 26 random rays, each under five or more windows, and the stacks: every row of every table is checked, and the
        // coverage counts below (both answers, full and empty tables) must still hold on them.
        var random = new SeededRandom(20261122);
        var cases = new List<OracleCase>();
        cases.AddRange(RandomCases("mixed", MixedScene.Value, random, rays: 12));
        cases.AddRange(RandomCases("fixed-point", FixedPointScene.Value, random, rays: 8));
        cases.AddRange(RandomCases("qornell-8", QornellScene.Value, random, rays: 6));
        cases.AddRange(StackCases());
        cases = cases.Select(c => c with { Input = c.Input with { Construction = Construction(construction) } }).ToList();

        // Every basis state of every case in one simulation per case: the oracle on the superposition of all rows, each
        // branch labelled by its row and checked against verify-rpc (CheckIntersectionOracleOnEveryRow).
        var expected = cases.Select(c => Enumerable.Range(0, c.Input.Table.Count).Select(p => c.Input.Table.Verify(p, c.Input.Window)).ToArray()).ToArray();
        var held = Check(cases, expected);
        var failed = Enumerable.Range(0, cases.Count).Where(c => !held[c]).ToArray();
        if (failed.Length > 0)
        {
            // Which rows: each basis state of the failed cases alone, its output and registers measured.
            var rows = Evaluate(failed.Select(c => cases[c]).ToList());
            for (var f = 0; f < failed.Length; f++)
            {
                var (table, window) = (cases[failed[f]].Input.Table, cases[failed[f]].Input.Window);
                Assert.Equal(table.Count, rows[f].Length);
                for (var p = 0; p < table.Count; p++)
                {
                    var (output, registers) = rows[f][p];
                    Assert.True(output == table.Verify(p, window), $"{cases[failed[f]]}, row {p}: oracle says {output}, verify-rpc says {!output}");
                    Assert.True(registers.SequenceEqual([p, 0, 0, 0, 0, 0, 0]),
                        $"{cases[failed[f]]}, row {p}: [index, rpc, coord, axis flags, valid, depth, depth flags] ended as [{string.Join(", ", registers)}], expected [{p}, 0, 0, 0, 0, 0, 0]");
                }
            }
            Assert.Fail($"{cases[failed[0]]}: each basis state alone passes, but on the superposition of the rows the oracle loses a branch or leaves one a phase of its own");
        }
        int marked = 0, unmarked = 0, allMarked = 0, noneMarked = 0;
        foreach (var outputs in expected)
        {
            var hits = outputs.Count(o => o);
            marked += hits;
            unmarked += outputs.Length - hits;
            if (hits == outputs.Length) allMarked++;
            if (hits == 0) noneMarked++;
        }
        // The random rays must exercise both answers, and the extreme tables must occur.
        Assert.True(marked >= 50 && unmarked >= 50, $"{marked} marked and {unmarked} unmarked rows");
        Assert.True(allMarked >= 1 && noneMarked >= 1, $"{allMarked} tables fully marked, {noneMarked} empty");
    }

    [Fact]
    public void GroverRunsSucceedWithTheClosedFormProbability()
    {
        var random = new SeededRandom(7);
        var mixed = RandomCases("mixed", MixedScene.Value, random, rays: 24).Where(c => c.Name.EndsWith("full range")).ToArray();
        var qornell = RandomCases("qornell-8", QornellScene.Value, random, rays: 12).Where(c => c.Name.EndsWith("full range")).ToArray();
        var stack = StackCases().ToArray();
        var runs = new (OracleCase Case, int Iterations)[]
        {
            (mixed.First(c => Marked(c).MarkedCount == 1), 1),
            (mixed.First(c => Marked(c).MarkedCount == 2), 1),
            (qornell.First(c => Marked(c).MarkedCount == 1), 2),
            (qornell.First(c => Marked(c).MarkedCount >= 2), 1),
            (stack[0], 1), // all six rows marked: certain success
            (stack.First(c => Marked(c).MarkedCount == 0), 2), // nothing marked: certain failure
        };
        // Each run's shots reject one iteration fewer or more and one marked row fewer or more with probability ≥ 0.99
        // (EngineDistributionChecks.ShotsFor, in steps of 10: 160 for N = 5, t = 1; 240 for N = 8, t = 1, r = 2; 30 to 120 for
        // the qornell run with t ≥ 2; 10 for the certain runs), where 300 each gave most far more. The run whose whole
        // distribution is fitted keeps its 300 shots. False-failure probability per check unchanged.
        var shots = runs.Select((r, k) => k == 1 ? 300 : EngineDistributionChecks.ShotsFor(Marked(r.Case).Count, Marked(r.Case).MarkedCount, r.Iterations, step: 10)).ToArray();
        var requests = runs.SelectMany((r, k) => Enumerable.Repeat(new GroverRequest(Marked(r.Case), r.Iterations, r.Case.Input), shots[k])).ToArray();
        var measured = Engine.Measure(requests);
        for (var k = 0; k < runs.Length; k++)
        {
            var set = Marked(runs[k].Case);
            var outcomes = measured.Skip(shots.Take(k).Sum()).Take(shots[k]).ToArray();
            var what = $"gate, {runs[k].Case}, N = {set.Count}, t = {set.MarkedCount}, r = {runs[k].Iterations}";
            StatisticalBounds.AssertBinomial(outcomes.Count(set.Contains), SuccessProbability(set, runs[k].Iterations), shots[k], what);
            if (k == 1)
            {
                // N = 5, not a power of two: every outcome, marked or not, has its exact probability,
                // which also checks the phases the oracle leaves on unmarked rows.
                StatisticalBounds.AssertFits(StatisticalBounds.Histogram(outcomes, set.Count), ExactDistribution(set, runs[k].Iterations), what);
            }
        }
    }

    [Fact]
    public void AdjointAndControlledIterationsUndoExactly()
    {
        // Each variant ends in a basis state, so every shot must match exactly; several shots draw
        // different outcomes of the unlookups' measurements.
        var random = new SeededRandom(31);
        var cases = new[]
        {
            RandomCases("mixed", MixedScene.Value, random, rays: 3).First(c => Marked(c).MarkedCount is > 0 and < 5),
            RandomCases("fixed-point", FixedPointScene.Value, random, rays: 3).First(c => Marked(c).MarkedCount > 0),
            RandomCases("qornell-8", QornellScene.Value, random, rays: 3).First(c => Marked(c).MarkedCount > 0),
        };
        var inputs = OracleConstruction.Named.SelectMany(construction => cases.Select(c =>
            new OracleCase($"{c.Name}, {construction}", c.Input with { Construction = construction }))).ToArray();
        var calls = inputs.SelectMany(c => Enumerable.Range(0, 3).Select(v => (Case: c, Variant: v))).ToArray();
        var expression = "[" + string.Join(", ", calls.Select(call =>
            $"QuantumRayTracing.Intersection.MeasureUndoneGateGroverIteration({GateEngine.OracleArgument(call.Case.Input)}, {call.Variant})")) + "]";
        foreach (var shot in fixture.Engine.Pool.Bridges[0].Run(expression, shots: 4))
        {
            var results = Regex.Matches(shot, @"\[(\d+), (\d+), (\d+), (\d+)\]").Select(m => m.Value).ToArray();
            Assert.Equal(calls.Length, results.Length);
            for (var k = 0; k < calls.Length; k++)
                Assert.True(results[k] == (calls[k].Variant == 1 ? "[0, 1, 0, 1]" : "[0, 0, 0, 1]"),
                    $"{calls[k].Case}, variant {calls[k].Variant}: [index, control, work, flag] = {results[k]}");
        }
    }

    [Fact]
    public void ExpensiveRequestsAreSpreadOverCalls()
    {
        ChunkLimits Gate() => new(GateEngine.DefaultMaxRequestsPerCall, GateEngine.Cost, GateEngine.MaxCostPerCall);
        IEnumerable<GroverRequest> Runs(int count, int iterations, int times) =>
            Enumerable.Repeat(new GroverRequest(new MarkedSet(count, [0]), iterations), times);
        // N = 512 at r = 17 costs more than a call's budget: one run per call.
        Assert.All(BridgeBatches.Chunks(Runs(512, 17, 10).ToArray(), 2, Gate()), c => Assert.Equal(1, c.Length));
        // N = 128 at r = 8: twenty runs fill a budget.
        Assert.Equal([20, 20, 10], BridgeBatches.Chunks(Runs(128, 8, 50).ToArray(), 2, Gate()).Select(c => c.Length));
        // Cheap runs: 300 at a cap of 100 on 2 workers take 2 waves of 2 calls, so 4 equal calls of 75.
        Assert.Equal([75, 75, 75, 75], BridgeBatches.Chunks(Runs(8, 2, 300).ToArray(), 2, Gate()).Select(c => c.Length));
        Assert.Equal([3, 3], BridgeBatches.Chunks(Runs(8, 2, 6).ToArray(), 2, Gate()).Select(c => c.Length));
        // Mixed costs stay in order and cover every request once.
        var mixed = Runs(8, 1, 5).Concat(Runs(512, 17, 2)).Concat(Runs(64, 3, 5)).ToArray();
        var chunks = BridgeBatches.Chunks(mixed, 2, Gate());
        Assert.Equal(Enumerable.Range(0, mixed.Length), chunks.SelectMany(c => Enumerable.Range(c.Start, c.Length)));
        Assert.Equal([5, 1, 1, 5], chunks.Select(c => c.Length));
    }

    [Fact]
    public void RequestsWithoutAnOracleAreRejected()
    {
        var bare = new GroverRequest(new MarkedSet(8, [1]), 1);
        var error = Assert.Throws<ArgumentException>(() => Engine.Measure([bare]));
        Assert.Contains("no oracle input", error.Message);
    }

    [Fact]
    public void EmptyBatchNeedsNoCall() => Assert.Empty(Engine.Measure([]));

    [Fact]
    public void ArgumentTextListsTheTableAndClampedConstants()
    {
        var geometry = StackScene.Value;
        var table = RayTable.Build(geometry, new Ray(new Vec3(7.5, 7.5, 0), new Vec3(0, 0, 1)));
        var input = new OracleInput(table, HitWindow.Range(3, Ray.Unbounded, geometry.Count));
        // Planes spanning [0, 15) in x and y hold the cells 0..14 (SceneGeometry: half-open spans).
        Assert.Equal(
            "new QuantumRayTracing.Intersection.IntersectionInput { CoordinateBits = 4, DepthBits = 4, "
            + "Bounds = [[0, 14, 0, 14, 2, 2], [0, 14, 0, 14, 4, 4], [0, 14, 0, 14, 6, 6], [0, 14, 0, 14, 8, 8], [0, 14, 0, 14, 10, 10], [0, 14, 0, 14, 12, 12]], "
            + "Points = [[7, 7, 2], [7, 7, 4], [7, 7, 6], [7, 7, 8], [7, 7, 10], [7, 7, 12]], "
            + "Valid = [true, true, true, true, true, true], Depths = [2, 4, 6, 8, 10, 12], Near = 3, Limit = 128, "
            + "FlatAxes = [2, 2, 2, 2, 2, 2], Construction = new QuantumRayTracing.Intersection.OracleConstruction { InPlaneAxes = false, BothBounds = true, MeasuredUnload = false, ConstantBounds = false } }",
            GateEngine.OracleArgument(input with { Construction = new OracleConstruction("test", InPlaneAxes: false, BothBounds: true, MeasuredUnload: false) }));
    }

    [Theory]
    // 4 depth bits, 3 index bits (N = 6): the limit is depth · 8 + id, at most 2^7.
    [InlineData(0, int.MaxValue, 6, 0, 128)]   // unbounded far: always below the limit
    [InlineData(0, 16, 0, 0, 128)]             // limit depth 2^d: as unbounded
    [InlineData(0, 15, 6, 0, 126)]             // far = 15, every id
    [InlineData(0, 15, 8, 0, 128)]             // every id of the last depth: the register's end
    [InlineData(0, 15, 100, 0, 128)]           // an id beyond 2^n acts as 2^n
    [InlineData(0, 6, 2, 0, 50)]               // strict order: (6, 2)
    [InlineData(0, 6, -3, 0, 48)]              // a negative id acts as 0
    [InlineData(0, 0, 0, 0, 0)]                // nothing is below (0, 0)
    [InlineData(0, -5, 3, 0, 0)]               // nor below a negative depth
    [InlineData(-7, 9, 0, 0, 72)]              // near below 0 always holds
    [InlineData(16, 9, 0, 16, 72)]             // near at 2^d never holds
    [InlineData(int.MaxValue, 9, 0, 16, 72)]
    public void ComparatorConstantsAreClampedToTheRegisters(int near, int limitDepth, int limitId, long expectedNear, long expectedLimit)
    {
        var geometry = StackScene.Value;
        var table = RayTable.Build(geometry, new Ray(new Vec3(7.5, 7.5, 0), new Vec3(0, 0, 1)));
        Assert.Equal((4, 3), (table.DepthBits, geometry.IndexBits));
        var constants = OracleConstants.For(new OracleInput(table, new HitWindow(near, limitDepth, limitId)));
        Assert.Equal(new OracleConstants(expectedNear, expectedLimit), constants);
    }

    [Fact]
    public void ClampedConstantsKeepVerifyRpcsAnswers()
    {
        // Every window of the theory above, on every row: the constants' comparisons agree with the window.
        var geometry = StackScene.Value;
        var table = RayTable.Build(geometry, new Ray(new Vec3(7.5, 7.5, 0), new Vec3(0, 0, 1)));
        foreach (var window in ClampWindows(geometry.Count))
        {
            var constants = OracleConstants.For(new OracleInput(table, window));
            for (var p = 0; p < table.Count; p++)
            {
                var depth = table.Depth(p);
                var byConstants = depth >= constants.Near && ((long)depth << geometry.IndexBits) + p < constants.Limit;
                Assert.True(byConstants == window.Accepts(depth, p), $"{window}, row {p}");
            }
        }
    }

    [Fact]
    public void RegisterCountMatchesTheResourceEstimator()
    {
        var random = new SeededRandom(99);
        var inputs = new[]
        {
            RandomCases("mixed", MixedScene.Value, random, rays: 1)[0].Input,
            RandomCases("fixed-point", FixedPointScene.Value, random, rays: 1)[2].Input,
            RandomCases("qornell-8", QornellScene.Value, random, rays: 1)[1].Input,
            StackCases().Last().Input,
            CameraRayInput("qornell-64.json", HitWindow.Closer(0, 21, 1, TieBreak.Strict)),
            CameraRayInput("qornell-512.json", null),
        };
        var bridge = fixture.Engine.Pool.Bridges[0];
        foreach (var construction in OracleConstruction.Named)
        {
            foreach (var input in inputs.Select(i => i with { Construction = construction }))
            {
                var registers = OracleRegisters.For(input);
                var argument = GateEngine.OracleArgument(input);
                var counts = bridge.Estimate($"QuantumRayTracing.Intersection.ApplyGateGroverIterationOnNewRegisters({argument})")[0]!["logicalCounts"]!;
                Assert.True(registers.PeakQubits == counts["numQubits"]!.GetValue<int>(), $"{construction}, {registers}: estimator {counts.ToJsonString()}");
                var oracle = OracleRegisters.ForOracle(input);
                var oracleCounts = bridge.Estimate($"QuantumRayTracing.Intersection.ApplyIntersectionOracleOnNewRegisters({argument})")[0]!["logicalCounts"]!;
                Assert.True(oracle.PeakQubits == oracleCounts["numQubits"]!.GetValue<int>(), $"{construction}, oracle alone, {oracle}: estimator {oracleCounts.ToJsonString()}");
            }
        }
    }

    private static OracleConstruction Construction(string name) => OracleConstruction.Named.Single(c => c.Name == name);

    /// <summary>The camera ray through pixel (80, 80) of a shipped scene, with a window (null: its full range).</summary>
    private static OracleInput CameraRayInput(string file, HitWindow? window)
    {
        var scene = SceneLoader.Load(Path.Combine(RepositoryPaths.Scenes, file));
        var table = RayTable.Build(new SceneGeometry(scene), CameraRays.For(scene.Camera, scene.Width, scene.Height)[80 * scene.Width + 80]);
        return new OracleInput(table, window ?? table.FullRange);
    }

    private static MarkedSet Marked(OracleCase c) => c.Input.Table.Marked(c.Input.Window);

    /// <summary>sin²((2r+1)θ) with sin²θ = t/N.</summary>
    private static double SuccessProbability(MarkedSet set, int iterations)
    {
        if (set.MarkedCount == set.Count) return 1.0;
        var theta = Math.Asin(Math.Sqrt((double)set.MarkedCount / set.Count));
        return Math.Pow(Math.Sin((2 * iterations + 1) * theta), 2);
    }

    /// <summary>The success probability spread evenly over the marked rows, the rest evenly over the unmarked.</summary>
    private static double[] ExactDistribution(MarkedSet set, int iterations)
    {
        var p = SuccessProbability(set, iterations);
        return Enumerable.Range(0, set.Count)
            .Select(i => set.Contains(i) ? p / set.MarkedCount : (1 - p) / (set.Count - set.MarkedCount))
            .ToArray();
    }

    private static IEnumerable<HitWindow> ClampWindows(int count) =>
    [
        new(0, int.MaxValue, count), new(0, 16, 0), new(0, 15, 6), new(0, 15, 8), new(0, 15, 100), new(0, 6, 2),
        new(0, 6, -3), new(0, 0, 0), new(0, -5, 3), new(-7, 9, 0), new(16, 9, 0), new(int.MaxValue, 9, 0), new(5, 8, 3),
    ];

    /// <summary>
    /// Rays from random points of the grid's cube towards random points of random primitives (so most
    /// hit something), some leaving from a primitive; each with five windows: the full range, a random
    /// [near, far], the strict and the random tie-break below a random row, and a near cutting the
    /// middle of the depths with an unbounded far.
    /// </summary>
    private static List<OracleCase> RandomCases(string scene, SceneGeometry geometry, SeededRandom random, int rays)
    {
        var cases = new List<OracleCase>();
        var side = geometry.Grid.Max;
        for (var r = 0; r < rays; r++)
        {
            var origin = new Vec3(random.NextDouble() * side, random.NextDouble() * side, random.NextDouble() * side);
            var target = (Rectangle)geometry.Primitives[random.NextInt(geometry.Count)];
            var aim = new Vec3(
                target.Min.X + random.NextDouble() * (target.Max.X - target.Min.X),
                target.Min.Y + random.NextDouble() * (target.Max.Y - target.Min.Y),
                target.Min.Z + random.NextDouble() * (target.Max.Z - target.Min.Z));
            if ((aim - origin).Length < 1e-6) continue;
            var excluded = random.NextInt(5) == 0 ? random.NextInt(geometry.Count) : -1;
            var table = RayTable.Build(geometry, new Ray(origin, aim - origin, ExcludedPrimitive: excluded));
            var depths = Enumerable.Range(0, table.Count).Where(table.IsValid).Select(table.Depth).Order().ToArray();
            var top = depths.Length > 0 ? depths[^1] : 0;
            var near = random.NextInt(top + 1);
            var best = random.NextInt(table.Count);
            var name = $"{scene} ray {r} ({origin} → {aim}, excluding {excluded})";
            cases.Add(new(name + ", full range", new OracleInput(table, table.FullRange)));
            cases.Add(new(name + ", random range", new OracleInput(table, HitWindow.Range(near, near + random.NextInt(top - near + 2), table.Count))));
            cases.Add(new(name + ", closer, strict", new OracleInput(table, HitWindow.Closer(0, table.Depth(best), best, TieBreak.Strict))));
            cases.Add(new(name + ", closer, random", new OracleInput(table, HitWindow.Closer(0, table.Depth(best), best, TieBreak.Random))));
            var middle = depths.Length > 0 ? depths[depths.Length / 2] : 0;
            cases.Add(new(name + ", near cut, unbounded", new OracleInput(table, HitWindow.Range(middle, Ray.Unbounded, table.Count))));
        }
        return cases;
    }

    /// <summary>The stack hit through every plane: all rows marked, none, and windows between.</summary>
    private static IEnumerable<OracleCase> StackCases()
    {
        var geometry = StackScene.Value;
        var table = RayTable.Build(geometry, new Ray(new Vec3(7.5, 7.5, 0), new Vec3(0, 0, 1)));
        yield return new("stack, unbounded", new OracleInput(table, table.FullRange));
        yield return new("stack, nothing below (0, 0)", new OracleInput(table, new HitWindow(0, 0, 0)));
        yield return new("stack, near beyond every depth", new OracleInput(table, HitWindow.Range(13, Ray.Unbounded, geometry.Count)));
        yield return new("stack, closer than (8, 3) strict", new OracleInput(table, HitWindow.Closer(3, 8, 3, TieBreak.Strict)));
        yield return new("stack, [4, 10]", new OracleInput(table, HitWindow.Range(4, 10, geometry.Count)));
        var away = RayTable.Build(geometry, new Ray(new Vec3(7.5, 7.5, 14), new Vec3(0.3, 0.2, 1)));
        yield return new("stack, ray leaving the stack", new OracleInput(away, away.FullRange));
    }

    /// <summary>Checks the oracle on every basis state of each case against <paramref name="expected"/>, in one call per worker.</summary>
    private bool[] Check(IReadOnlyList<OracleCase> cases, bool[][] expected)
    {
        var pool = fixture.Engine.Pool;
        var results = new bool[cases.Count];
        var chunkSize = (cases.Count + pool.Workers - 1) / pool.Workers;
        var chunks = Enumerable.Range(0, (cases.Count + chunkSize - 1) / chunkSize).ToArray();
        pool.ForEach(chunks, (chunk, bridge) =>
        {
            var range = Enumerable.Range(chunk * chunkSize, Math.Min(chunkSize, cases.Count - chunk * chunkSize)).ToArray();
            var inputs = string.Join(", ", range.Select(c => GateEngine.OracleArgument(cases[c].Input)));
            var outputs = string.Join(", ", range.Select(c => "[" + string.Join(", ", expected[c].Select(o => o ? "true" : "false")) + "]"));
            var held = bridge.Run($"{CheckOperation}([{inputs}], [{outputs}])")[0].Trim('[', ']').Split(", ");
            Assert.Equal(range.Length, held.Length);
            for (var k = 0; k < range.Length; k++) results[range[k]] = held[k] == "true";
        });
        return results;
    }

    /// <summary>Runs the oracle on every basis state of every case, in one call per worker.</summary>
    private (bool Output, int[] Registers)[][] Evaluate(IReadOnlyList<OracleCase> cases)
    {
        var pool = fixture.Engine.Pool;
        var results = new (bool, int[])[cases.Count][];
        var chunkSize = (cases.Count + pool.Workers - 1) / pool.Workers;
        var chunks = Enumerable.Range(0, (cases.Count + chunkSize - 1) / chunkSize).ToArray();
        pool.ForEach(chunks, (chunk, bridge) =>
        {
            var slice = cases.Skip(chunk * chunkSize).Take(chunkSize).ToArray();
            var text = bridge.Run($"{EvaluateOperation}([{string.Join(", ", slice.Select(c => GateEngine.OracleArgument(c.Input)))}])")[0];
            var rows = RowResult().Matches(text)
                .Select(m => (m.Groups[1].Value == "true", m.Groups[2].Value.Split(", ").Select(int.Parse).ToArray()))
                .ToArray();
            var next = 0;
            for (var k = 0; k < slice.Length; k++)
            {
                var n = slice[k].Input.Table.Count;
                Assert.True(next + n <= rows.Length, $"{EvaluateOperation} returned {rows.Length} rows, fewer than the cases hold");
                results[chunk * chunkSize + k] = rows[next..(next + n)];
                next += n;
            }
            Assert.Equal(next, rows.Length);
        });
        return results;
    }

    /// <summary>One row of the Q# result: <c>(true, [3, 0, 0, 0, 0, 0, 0])</c>.</summary>
    [GeneratedRegex(@"\((true|false), \[([0-9, ]+)\]\)")]
    private static partial Regex RowResult();
}
