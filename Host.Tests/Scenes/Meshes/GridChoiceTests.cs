using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Meshes;

namespace QuantumRayTracing.Tests.Scenes.Meshes;

/// <summary>The rule (GridChoice's summary, docs/scenes.md) on meshes small enough to work by hand.</summary>
public sealed class GridChoiceTests
{
    /// <summary>Triangles from corners in threes: corners 3k, 3k + 1 and 3k + 2 make triangle k.</summary>
    private static TriangleMesh Mesh(params Vec3[] corners) =>
        new(corners, Enumerable.Range(0, corners.Length / 3).Select(k => new MeshTriangle(3 * k, 3 * k + 1, 3 * k + 2)).ToArray());

    /// <summary>
    /// Corners (0,0,0) (3,0,0) (0,3,0): extent 3; I = 2 since 2^1 − 1 = 1 &lt; 3 ≤ 2^2 − 1 = 3. Smallest edge 3;
    /// F = 1 since 3·2^0 = 3 &lt; 4 ≤ 3·2^1 = 6. A 2.1 grid: every corner already on it, nothing moves.
    /// </summary>
    [Fact]
    public void IntegerTriangle()
    {
        var mesh = Mesh(new(0, 0, 0), new(3, 0, 0), new(0, 3, 0));
        var choice = GridChoice.For(mesh, "t");
        Assert.Equal(new CoordinateGrid(2, 1), choice.Grid);
        Assert.Equal(Vec3.Zero, choice.Offset);
        var onGrid = choice.Quantise(mesh, "t");
        Assert.Equal((0, 0.0), (onGrid.Collapsed, onGrid.LargestDisplacement));
        Assert.Equal(mesh.Vertices, onGrid.Mesh.Vertices);
    }

    /// <summary>
    /// Corners (−2,5,1) (8,5,1) (−2,5.3,1): bounds min (−2,5,1), so the offset is (2,−5,−1) and the corners land on
    /// (0,0,0) (10,0,0) (0,0.3,0). Extent 10: I = 4 (7 &lt; 10 ≤ 15). Smallest edge 0.3: F = 4 (0.3·8 = 2.4 &lt; 4 ≤
    /// 0.3·16 = 4.8). Step 1/16: 0.3 is 4.8 steps, rounded to 5 = 0.3125, a displacement of 0.0125; the other
    /// corners are whole numbers and do not move. (The placed y is 5.3 − 5, 0.2999999999999998 in doubles: still 5 steps.)
    /// </summary>
    [Fact]
    public void PlacedAtTheOriginAndRounded()
    {
        var mesh = Mesh(new(-2, 5, 1), new(8, 5, 1), new(-2, 5.3, 1));
        var choice = GridChoice.For(mesh, "t");
        Assert.Equal(new Vec3(2, -5, -1), choice.Offset);
        Assert.Equal(10, choice.Extent);
        Assert.Equal(new CoordinateGrid(4, 4), choice.Grid);
        Assert.False(choice.Capped);
        var onGrid = choice.Quantise(mesh, "t");
        Assert.Equal([new(0, 0, 0), new(10, 0, 0), new(0, 0.3125, 0)], onGrid.Mesh.Vertices);
        Assert.Equal(0.0125, onGrid.LargestDisplacement, 1e-12);
        Assert.Equal(0, onGrid.Collapsed);
    }

    /// <summary>
    /// A 1000-unit triangle (0,0,0) (1000,0,0) (0,1000,0) and a sliver (0,0,0) (1000,0,0) (0,0.001,0). Extent 1000:
    /// I = 10 (511 &lt; 1000 ≤ 1023). The sliver's 0.001 edge asks for F = 12 (0.001·2^11 = 2.05 &lt; 4 ≤ 0.001·2^12 =
    /// 4.1), but 10 + 12 > 16, so F = 6: steps of 1/64, and 0.001 rounds to 0: the sliver collapses onto the x axis
    /// and is dropped; the big triangle stays.
    /// </summary>
    [Fact]
    public void CappedAtSixteenBitsAndASliverDropped()
    {
        var mesh = Mesh(new(0, 0, 0), new(1000, 0, 0), new(0, 1000, 0), new(0, 0, 0), new(1000, 0, 0), new(0, 0.001, 0));
        var choice = GridChoice.For(mesh, "t");
        Assert.Equal(new CoordinateGrid(10, 6), choice.Grid);
        Assert.True(choice.Capped);
        var onGrid = choice.Quantise(mesh, "t");
        Assert.Equal(1, onGrid.Collapsed);
        Assert.Equal([new MeshTriangle(0, 1, 2)], onGrid.Mesh.Triangles);
        Assert.Equal(0.001, onGrid.LargestDisplacement, 1e-15);
    }

    /// <summary>The sliver alone: the same 10.6 grid, and with its one triangle collapsed there is nothing left.</summary>
    [Fact]
    public void EveryTriangleCollapsingIsAnError()
    {
        var mesh = Mesh(new(0, 0, 0), new(1000, 0, 0), new(0, 0.001, 0));
        var choice = GridChoice.For(mesh, "sliver.obj");
        var error = Assert.Throws<MeshError>(() => choice.Quantise(mesh, "sliver.obj"));
        Assert.StartsWith("sliver.obj: grid: the only triangle collapses on the 10.6 fixed-point grid", error.Message);
    }

    /// <summary>Extent 65,535 = 2^16 − 1 still fits 16 integer bits (and no fraction bits); 65,536 would need 17.</summary>
    [Fact]
    public void SixteenIntegerBitsAtMost()
    {
        var fits = Mesh(new(0, 0, 0), new(65535, 0, 0), new(0, 65535, 0));
        Assert.Equal(new CoordinateGrid(16, 0), GridChoice.For(fits, "t").Grid);
        var error = Assert.Throws<MeshError>(() => GridChoice.For(Mesh(new(0, 0, 0), new(65536, 0, 0), new(0, 1, 0)), "big.obj"));
        Assert.Equal("big.obj: bounds: the mesh spans 65536 units; a 16-bit grid reaches 65535: scale it down", error.Message);
    }

    /// <summary>
    /// An edge of 0.01 in a unit-sized mesh: extent 1, I = 1 (2^1 − 1 = 1 ≥ 1); F = 9 (0.01·256 = 2.56 &lt; 4 ≤
    /// 0.01·512 = 5.12). The smallest edge spans 5.12 steps.
    /// </summary>
    [Fact]
    public void FractionBitsFromTheSmallestEdge()
    {
        var choice = GridChoice.For(Mesh(new(0, 0, 0), new(1, 0, 0), new(0, 1, 0), new(0, 0, 0), new(0.01, 0, 0), new(0, 0.01, 0)), "t");
        Assert.Equal(new CoordinateGrid(1, 9), choice.Grid);
        Assert.Equal(5.12, choice.StepsOnSmallestEdge, 1e-12);
    }

    [Fact]
    public void DegenerateTrianglesAreDroppedAndCounted()
    {
        var mesh = Mesh(new(0, 0, 0), new(1, 0, 0), new(0, 1, 0), new(0, 0, 0), new(1, 1, 1), new(2, 2, 2), new(5, 5, 5), new(5, 5, 5), new(0, 1, 0));
        var (kept, dropped) = mesh.WithoutDegenerate();
        Assert.Equal(2, dropped);
        Assert.Equal([new MeshTriangle(0, 1, 2)], kept.Triangles);
        // The collinear triangle's edges (√3 and 2√3) count; the repeated corner's zero edge does not.
        Assert.Equal(1, mesh.SmallestEdge);
    }
}
