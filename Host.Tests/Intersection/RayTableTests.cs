using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Intersection;

/// <summary>eval-rpc (quantised point and depth) and verify-rpc on hand-computed cases.</summary>
public class RayTableTests
{
    // 4-bit integer grid (0..15): a square in the plane z = 8 and a wall in the plane x = 10.
    private static readonly Scene Integer = With(4, 0,
        Rect(2, 2, 8, 6, 6, 8),
        Rect(10, 0, 0, 10, 8, 8));

    // 3.2 fixed-point grid: steps of 0.25, values 0..7.75, grid integers 0..31 (scale 4).
    // The rectangle spans x 1.25..3.5 (grid 5..14), y 0.5..2.75 (grid 2..11) in the plane z = 4.5 (grid 18).
    private static readonly Scene Fixed = With(3, 2, Rect(1.25, 0.5, 4.5, 3.5, 2.75, 4.5));

    private static void AssertRow(RayTable table, int p, int x, int y, int z, int depth)
    {
        Assert.True(table.IsValid(p), $"row {p} should be valid");
        Assert.Equal((x, y, z), (table.Point(p, 0), table.Point(p, 1), table.Point(p, 2)));
        Assert.Equal(depth, table.Depth(p));
    }

    private static void AssertInvalid(RayTable table, int p)
    {
        Assert.False(table.IsValid(p), $"row {p} should be invalid");
        Assert.Equal((0, 0, 0, 0), (table.Point(p, 0), table.Point(p, 1), table.Point(p, 2), table.Depth(p)));
        Assert.False(table.Verify(p, HitWindow.Range(0, int.MaxValue, table.Count)));
        Assert.False(table.Marked(table.FullRange).Contains(p));
    }

    [Fact]
    public void IntegerGridPointAndDepthAlongThePrincipalAxis()
    {
        // Direction (0.2, 0.1, 2): principal axis z. Plane z = 8 at t = 8 / 2 = 4:
        // point (3.7 + 0.8, 4.2 + 0.4, 8) = (4.5, 4.6, 8) → floor (4, 4, 8); depth = t · |dz| = 4 · 2 = 8.
        var table = Table(Integer, new Ray(new Vec3(3.7, 4.2, 0), new Vec3(0.2, 0.1, 2)));
        AssertRow(table, 0, 4, 4, 8, 8);
        Assert.Equal(4, table.Distance(0), 12);
        Assert.True(table.Verify(0, table.FullRange));
        // Plane x = 10 at t = (10 − 3.7) / 0.2 = 31.5: z = 63, outside the 4-bit grid.
        Assert.False(table.IsValid(1));
    }

    [Fact]
    public void DepthIsMeasuredAlongAnXPrincipalAxis()
    {
        // Direction (3, 0.5, -0.25): principal axis x. Plane x = 10 at t = (10 − 1) / 3 = 3:
        // point (10, 3.5 + 1.5, 2.5 − 0.75) = (10, 5, 1.75) → (10, 5, 1); depth = 3 · 3 = 9 (not the Euclidean 9.13).
        var table = Table(Integer, new Ray(new Vec3(1, 3.5, 2.5), new Vec3(3, 0.5, -0.25)));
        Assert.Equal(0, table.Ray.PrincipalAxis);
        AssertRow(table, 1, 10, 5, 1, 9);
        Assert.True(table.Verify(1, table.FullRange));
    }

    [Fact]
    public void DepthIsFlooredLikeThePoint()
    {
        // From z = 0.5 to the plane z = 8: depth 7.5 → 7.
        var table = Table(Integer, new Ray(new Vec3(3.5, 3.5, 0.5), new Vec3(0, 0, 1)));
        AssertRow(table, 0, 3, 3, 8, 7);
    }

    [Fact]
    public void PointsAreFlooredAfterTheSnapTolerance()
    {
        // 3 − 1e-10 is within the 1e-9 snap of the grid line 3, so it lands on 3; 3 − 1e-8 is not, so it floors to 2.
        Assert.Equal(3, Table(Integer, new Ray(new Vec3(3 - 1e-10, 4, 0), new Vec3(0, 0, 1))).Point(0, 0));
        Assert.Equal(2, Table(Integer, new Ray(new Vec3(3 - 1e-8, 4, 0), new Vec3(0, 0, 1))).Point(0, 0));
        Assert.Equal(3, RayTable.Quantise(3 - 1e-10, 1));
        Assert.Equal(2, RayTable.Quantise(3 - 1e-8, 1));
        Assert.Equal(-1, RayTable.Quantise(-0.5, 1));
        // Fixed point: 1.2 · 4 = 4.8 → 4; 1.25 · 4 = 5.
        Assert.Equal(4, RayTable.Quantise(1.2, 4));
        Assert.Equal(5, RayTable.Quantise(1.25, 4));
    }

    [Fact]
    public void FixedPointGridPointAndDepth()
    {
        // Direction (0.1, −0.05, 1), origin z = 0.5: plane z = 4.5 at t = 4:
        // point (2.1 + 0.4, 1.3 − 0.2, 4.5) = (2.5, 1.1, 4.5), · 4 = (10, 4.4, 18) → (10, 4, 18);
        // depth 4 world units = 16 grid units, which needs 5 bits.
        var table = Table(Fixed, new Ray(new Vec3(2.1, 1.3, 0.5), new Vec3(0.1, -0.05, 1)));
        AssertRow(table, 0, 10, 4, 18, 16);
        Assert.True(table.Verify(0, table.FullRange));
        Assert.Equal(5, table.DepthBits);
        Assert.Equal(5, table.CoordinateBits);
        // Cells held: x from 5 up to one step below the max corner 14, y from 2 to one below 11.
        Assert.Equal((5, 13), (table.Geometry.Min(0, 0), table.Geometry.Max(0, 0)));
        Assert.Equal((2, 10), (table.Geometry.Min(0, 1), table.Geometry.Max(0, 1)));
        Assert.Equal((18, 18), (table.Geometry.Min(0, 2), table.Geometry.Max(0, 2)));
    }

    [Theory]
    [InlineData(1.25, 0.5, true)]    // min corner (5, 2)
    [InlineData(1.25, 1.0, true)]    // min-x edge (5, 4)
    [InlineData(2.0, 0.5, true)]     // min-y edge (8, 2)
    [InlineData(3.49, 2.74, true)]   // (13.96, 10.96) floors to the last cell (13, 10)
    [InlineData(3.49, 1.0, true)]    // 13.96 → 13, the last x cell
    [InlineData(3.5, 2.75, false)]   // max corner (14, 11): the next rectangle's cell
    [InlineData(3.5, 1.0, false)]    // max-x edge 14
    [InlineData(2.0, 2.75, false)]   // max-y edge 11
    [InlineData(3.75, 1.0, false)]   // 15, past x max
    [InlineData(1.2, 1.0, false)]    // 4.8 → 4, below x min
    [InlineData(2.0, 0.45, false)]   // 1.8 → 1, below y min
    public void MinEdgesAreInsideMaxEdgesAreNot(double x, double y, bool inside)
    {
        // The rectangle spans [1.25, 3.5) x [0.5, 2.75): half-open, so tiles sharing an edge never both claim a point.
        var table = Table(Fixed, new Ray(new Vec3(x, y, 0), new Vec3(0, 0, 1)));
        Assert.True(table.IsValid(0));
        Assert.Equal(inside, table.Verify(0, table.FullRange));
    }

    [Fact]
    public void IntegerRectangleHoldsExactlyItsHalfOpenSpan()
    {
        // Square [2, 6) x [2, 6): the min corner and min edges are inside, up to 5.99; 6 and beyond, or below 2, are not.
        foreach (var (x, y) in new[] { (2.0, 2.0), (2.0, 4.0), (4.0, 2.0), (5.99, 5.99), (5.99, 4.0) })
            Assert.True(Table(Integer, new Ray(new Vec3(x, y, 0), new Vec3(0, 0, 1))).Verify(0, HitWindow.Range(0, 100, 2)), $"({x}, {y})");
        foreach (var (x, y) in new[] { (6.0, 6.0), (2.0, 6.0), (6.0, 2.0), (4.0, 6.0), (6.99, 4.0), (1.99, 4.0) })
            Assert.False(Table(Integer, new Ray(new Vec3(x, y, 0), new Vec3(0, 0, 1))).Verify(0, HitWindow.Range(0, 100, 2)), $"({x}, {y})");
    }

    [Fact]
    public void RayParallelToThePlaneGivesAnInvalidRow() =>
        AssertInvalid(Table(Integer, new Ray(new Vec3(0, 3, 4), new Vec3(1, 0.5, 0))), 0);

    [Fact]
    public void PlaneBehindOrAtTheOriginGivesAnInvalidRow()
    {
        // From z = 10 towards +z the plane z = 8 is at t = −2; from z = 8 it is at t = 0.
        AssertInvalid(Table(Integer, new Ray(new Vec3(3, 3, 10), new Vec3(0, 0, 1))), 0);
        AssertInvalid(Table(Integer, new Ray(new Vec3(3, 3, 8), new Vec3(0, 0, 1))), 0);
        // Turned around the same plane is ahead at t = 2.
        AssertRow(Table(Integer, new Ray(new Vec3(3, 3, 10), new Vec3(0, 0, -1))), 0, 3, 3, 8, 2);
    }

    [Fact]
    public void ExcludedPrimitiveGivesAnInvalidRow()
    {
        var origin = new Vec3(3, 3, 0);
        AssertInvalid(Table(Integer, new Ray(origin, new Vec3(0, 0, 1), ExcludedPrimitive: 0)), 0);
        AssertRow(Table(Integer, new Ray(origin, new Vec3(0, 0, 1), ExcludedPrimitive: 1)), 0, 3, 3, 8, 8);
    }

    [Fact]
    public void MaxDistanceIsExclusive()
    {
        // Direction (0, 0, 8): the plane z = 8 is at t = 1 exactly.
        var origin = new Vec3(3, 3, 0);
        AssertInvalid(Table(Integer, new Ray(origin, new Vec3(0, 0, 8), MaxDistance: 1)), 0);
        AssertInvalid(Table(Integer, new Ray(origin, new Vec3(0, 0, 8), MaxDistance: 0.5)), 0);
        AssertRow(Table(Integer, new Ray(origin, new Vec3(0, 0, 8), MaxDistance: 1.0001)), 0, 3, 3, 8, 8);
    }

    [Fact]
    public void PointOutsideTheGridGivesAnInvalidRow()
    {
        // Plane z = 8 at t = 8: x = 3 + 2 · 8 = 19 ≥ 16 and x = 3 − 8 = −5 < 0 are off the 4-bit grid;
        // x = 3 + 1.5 · 8 = 15 is on it (a valid row, outside the rectangle).
        AssertInvalid(Table(Integer, new Ray(new Vec3(3, 3, 0), new Vec3(2, 0, 1))), 0);
        AssertInvalid(Table(Integer, new Ray(new Vec3(3, 3, 0), new Vec3(-1, 0, 1))), 0);
        var edge = Table(Integer, new Ray(new Vec3(3, 3, 0), new Vec3(1.5, 0, 1)));
        AssertRow(edge, 0, 15, 3, 8, 12); // principal axis x: depth = 8 · 1.5 = 12
        Assert.False(edge.Verify(0, edge.FullRange));
        // Fixed point: x = 8 is one step past the largest grid value 7.75 (grid integer 32).
        AssertInvalid(Table(Fixed, new Ray(new Vec3(8, 1, 0), new Vec3(0, 0, 1))), 0);
    }

    [Fact]
    public void NearAndFarBoundTheDepth()
    {
        // Depth 8 to the plane z = 8; both limits are inclusive.
        var origin = new Vec3(3, 3, 0);
        bool Hits(int near, int far)
        {
            var table = Table(Integer, new Ray(origin, new Vec3(0, 0, 1), near, far));
            return table.Verify(0, table.FullRange);
        }
        Assert.True(Hits(8, 8));
        Assert.True(Hits(0, Ray.Unbounded));
        Assert.False(Hits(9, 20));
        Assert.False(Hits(0, 7));
    }

    // Planes crossed by the ray from (3.5, 3.5, 0) along +z, all at the point (3, 3, z):
    // id 0: z = 10 (depth 10), id 1: z = 4 (4), id 2: z = 8 (8), id 3: z = 8 (8, ties with id 2),
    // id 4: z = 6 but spans 5..8, so the point misses it (a valid row outside the rectangle),
    // id 5: a wall x = 12, parallel to the ray (invalid row).
    private static readonly Scene Stack = With(4, 0,
        Rect(0, 0, 10, 8, 8, 10),
        Rect(0, 0, 4, 8, 8, 4),
        Rect(0, 0, 8, 8, 8, 8),
        Rect(2, 2, 8, 6, 6, 8),
        Rect(5, 5, 6, 8, 8, 6),
        Rect(12, 0, 0, 12, 8, 8));

    public static TheoryData<string, int, int, int, int[]> Windows => new()
    {
        { "full range", 0, Ray.Unbounded, 6, [0, 1, 2, 3] },
        { "closer than (8, 3), strict", 0, 8, 3, [1, 2] },
        { "closer than (8, 2), strict", 0, 8, 2, [1] },
        { "closer than depth 8 (random ties)", 0, 8, 0, [1] },
        { "depth 5..10", 5, 10, 6, [0, 2, 3] },
        { "depth < 10 or (10, id < 1)", 0, 10, 1, [0, 1, 2, 3] },
        { "depth < 10 or (10, id < 0)", 0, 10, 0, [1, 2, 3] },
        { "depth 11..15", 11, 15, 6, [] },
    };

    [Theory]
    [MemberData(nameof(Windows))]
    public void MarkedIsExactlyTheRowsVerifyAccepts(string what, int near, int limitDepth, int limitId, int[] expected)
    {
        var table = Table(Stack, new Ray(new Vec3(3.5, 3.5, 0), new Vec3(0, 0, 1)));
        var window = new HitWindow(near, limitDepth, limitId);
        var marked = table.Marked(window);
        Assert.Equal(6, marked.Count);
        Assert.True(expected.SequenceEqual(marked.Indices.ToArray()), $"{what}: marked [{string.Join(", ", marked.Indices.ToArray())}]");
        for (var p = 0; p < table.Count; p++)
            Assert.Equal(expected.Contains(p), table.Verify(p, window));
    }

    [Fact]
    public void StackRowsAreAsComputedByHand()
    {
        var table = Table(Stack, new Ray(new Vec3(3.5, 3.5, 0), new Vec3(0, 0, 1)));
        int[] depths = [10, 4, 8, 8, 6];
        for (var p = 0; p < 5; p++) AssertRow(table, p, 3, 3, depths[p], depths[p]);
        Assert.False(table.IsValid(5));
        Assert.False(table.Verify(4, table.FullRange));
    }

    [Fact]
    public void DepthBitsAreTheBitsOfTheLargestValidDepth()
    {
        var origin = new Vec3(3.5, 3.5, 0);
        // Valid depths 10, 4, 8, 8, 6 (id 4's row is valid though outside its rectangle): 10 = 1010b, 4 bits.
        Assert.Equal(4, Table(Stack, new Ray(origin, new Vec3(0, 0, 1))).DepthBits);
        // Ending before t = 8 leaves depths 4 and 6: 6 = 110b, 3 bits; the invalid rows' depths do not count.
        Assert.Equal(3, Table(Stack, new Ray(origin, new Vec3(0, 0, 1), MaxDistance: 8)).DepthBits);
        // Ending just past t = 8 keeps depth 8 = 1000b: 4 bits.
        Assert.Equal(4, Table(Stack, new Ray(origin, new Vec3(0, 0, 1), MaxDistance: 8.5)).DepthBits);
        // Only depth 4 = 100b: 3 bits; no valid row at all: at least 1.
        Assert.Equal(3, Table(Stack, new Ray(origin, new Vec3(0, 0, 1), MaxDistance: 5)).DepthBits);
        Assert.Equal(1, Table(Stack, new Ray(origin, new Vec3(0, 0, 1), MaxDistance: 3)).DepthBits);
        // Excluding id 0 (depth 10) leaves the largest depth 8: still 4 bits.
        Assert.Equal(4, Table(Stack, new Ray(origin, new Vec3(0, 0, 1), ExcludedPrimitive: 0)).DepthBits);
        // From z = 3 up to t = 4: depths 1 (z = 4) and 3 (z = 6); 3 = 11b, 2 bits.
        Assert.Equal(2, Table(Stack, new Ray(new Vec3(3.5, 3.5, 3), new Vec3(0, 0, 1), MaxDistance: 4)).DepthBits);
    }

    /// <summary>The compact table built in one pass holds what the full table's compact form holds, on every broad random scene.</summary>
    [Fact]
    public void CompactBuiltDirectlyEqualsTheFullTablesCompactForm()
    {
        foreach (var kind in Scenes.BroadRandomScene.Kinds)
        {
            var scene = Scenes.BroadRandomScene.Build(kind, 11);
            var geometry = new SceneGeometry(scene);
            foreach (var ray in CameraRays.For(scene.Camera, 16, 16))
            {
                var (direct, compacted) = (RayTable.BuildCompact(geometry, ray), RayTable.Build(geometry, ray).Compact());
                Assert.True(direct.IsCompact);
                Assert.Equal(compacted.DepthBits, direct.DepthBits);
                var window = direct.FullRange;
                Assert.Equal(compacted.Marked(window).Indices.ToArray(), direct.Marked(window).Indices.ToArray());
                foreach (var p in compacted.Marked(window).Indices.ToArray())
                    Assert.Equal((compacted.Depth(p), compacted.Distance(p)), (direct.Depth(p), direct.Distance(p)));
            }
        }
    }

    /// <summary>
    /// The vectorised compact build against the scalar full table on secondary rays too: rays that leave a primitive
    /// (its row must be invalid and must not count in the depth bits), end at t = 1 like shadow rays, start inside the
    /// grid or point along an axis; every row's depth and distance bit for bit, on every broad random scene.
    /// </summary>
    [Fact]
    public void CompactBuildMatchesTheScalarRowsOnSecondaryRays()
    {
        var random = new QuantumRayTracing.Randomness.SeededRandom(5);
        foreach (var kind in Scenes.BroadRandomScene.Kinds)
        {
            var scene = Scenes.BroadRandomScene.Build(kind, 13);
            var geometry = new SceneGeometry(scene);
            var side = 1 << scene.Grid.IntegerBits;
            Vec3 Point() => new(random.NextDouble() * side, random.NextDouble() * side, random.NextDouble() * side);
            for (var k = 0; k < 400; k++)
            {
                var (from, to) = (Point(), Point());
                if (k % 4 == 1) from = new Vec3(Math.Floor(from.X), Math.Floor(from.Y), Math.Floor(from.Z)); // on grid lines: the snap decides
                var direction = k % 10 == 0 ? new Vec3(0, 0, k % 20 == 0 ? 1 : -1) : to - from;
                var ray = new Ray(from, direction, MaxDistance: k % 2 == 0 ? 1 : double.PositiveInfinity,
                    ExcludedPrimitive: k % 3 == 0 ? random.NextInt(geometry.Count) : -1);
                var (direct, full) = (RayTable.BuildCompact(geometry, ray), RayTable.Build(geometry, ray));
                Assert.Equal(full.DepthBits, direct.DepthBits);
                for (var p = 0; p < geometry.Count; p++)
                {
                    var inside = full.Verify(p, new HitWindow(0, int.MaxValue, int.MaxValue));
                    Assert.Equal(inside, direct.Verify(p, new HitWindow(0, int.MaxValue, int.MaxValue)));
                    if (inside) Assert.Equal((full.Depth(p), BitConverter.DoubleToInt64Bits(full.Distance(p))), (direct.Depth(p), BitConverter.DoubleToInt64Bits(direct.Distance(p))));
                }
                var window = new HitWindow(random.NextInt(4), random.NextInt(64), random.NextInt(geometry.Count + 1));
                Assert.Equal(QuantumRayTracing.Search.BestAccepted.Among(full, window, Enumerable.Range(0, geometry.Count)), direct.BestAccepted(window));
                Assert.Equal(QuantumRayTracing.Search.BestAccepted.Among(full, window, Enumerable.Range(0, geometry.Count)), full.BestAccepted(window));
            }
        }
    }
}
