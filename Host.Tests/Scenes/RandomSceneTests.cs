using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Tests.Scenes;

/// <summary>The random scenes the accuracy tests render: valid, reproducible from their seed, and each kind what it claims to be.</summary>
public sealed class RandomSceneTests
{
    [Theory]
    [MemberData(nameof(Kinds))]
    public void SameSeedSameSceneOtherSeedAnother(RandomSceneKind kind)
    {
        var first = RandomScene.Build(kind, 7);
        Assert.Equal(Corners(first), Corners(RandomScene.Build(kind, 7)));
        Assert.NotEqual(Corners(first), Corners(RandomScene.Build(kind, 8)));
    }

    [Fact]
    public void ScatteredHasACountThatIsNotAPowerOfTwo()
    {
        var count = RandomScene.Build(RandomSceneKind.Scattered, 1).Rectangles().Count;
        Assert.NotEqual(0, count & (count - 1));
    }

    [Fact]
    public void TiesOverlapAtEqualDepth()
    {
        // Two rectangles facing the camera at one z whose extents overlap: rays through the overlap meet equal depths.
        var rectangles = RandomScene.Build(RandomSceneKind.Ties, 1).Rectangles();
        var overlapping = rectangles.SelectMany((a, i) => rectangles.Skip(i + 1).Select(b => (a, b)))
            .Count(p => p.a.Min.Z == p.b.Min.Z && p.a.Min.X < p.b.Max.X && p.b.Min.X < p.a.Max.X && p.a.Min.Y < p.b.Max.Y && p.b.Min.Y < p.a.Max.Y);
        Assert.True(overlapping > 0);
    }

    [Fact]
    public void SharedEdgesMeetAlongWholeSides()
    {
        // Every box face shares each of its four edges with another rectangle of the scene.
        var rectangles = RandomScene.Build(RandomSceneKind.SharedEdges, 1).Rectangles();
        var edges = rectangles.SelectMany(Edges).GroupBy(e => e).Count(g => g.Count() >= 2);
        Assert.True(edges >= 4 * 12, $"{edges} shared edges");
    }

    [Fact]
    public void DeepHasFourThousandRectanglesAndDozensOnARay()
    {
        var scene = RandomScene.Build(RandomSceneKind.Deep, 1);
        Assert.Equal(4000, scene.Rectangles().Count);
        var centre = Rays.CameraRays.For(scene.Camera, 1, 1)[0];
        var table = RayTable.Build(new SceneGeometry(scene), centre);
        Assert.True(table.Marked(table.FullRange).MarkedCount >= 16, $"{table.Marked(table.FullRange).MarkedCount} on the centre ray");
    }

    [Fact]
    public void FractionalUsesQuarterUnits()
    {
        var scene = RandomScene.Build(RandomSceneKind.Fractional, 1);
        Assert.Equal(2, scene.Grid.FractionBits);
        Assert.Contains(scene.Rectangles(), r => new[] { r.Min.X, r.Min.Y, r.Min.Z, r.Max.X, r.Max.Y, r.Max.Z }.Any(c => c != Math.Floor(c)));
    }

    public static TheoryData<RandomSceneKind> Kinds() => [.. RandomScene.Kinds];

    private static string Corners(Scene scene) => string.Join(";", scene.Rectangles().Select(r => $"{r.Min}-{r.Max}"));

    private static IEnumerable<(Vec3, Vec3)> Edges(Rectangle r)
    {
        var corners = new[] { r.Min.X, r.Max.X }.SelectMany(x => new[] { r.Min.Y, r.Max.Y }.SelectMany(y => new[] { r.Min.Z, r.Max.Z }.Select(z => new Vec3(x, y, z))))
            .Distinct().ToArray();
        // The four corners of a flat rectangle; edges join corners differing on one axis.
        for (var i = 0; i < corners.Length; i++)
            for (var j = i + 1; j < corners.Length; j++)
            {
                var (a, b) = (corners[i], corners[j]);
                var differing = (a.X != b.X ? 1 : 0) + (a.Y != b.Y ? 1 : 0) + (a.Z != b.Z ? 1 : 0);
                if (differing == 1) yield return Order(a, b);
            }
    }

    private static (Vec3, Vec3) Order(Vec3 a, Vec3 b) =>
        (a.X, a.Y, a.Z).CompareTo((b.X, b.Y, b.Z)) <= 0 ? (a, b) : (b, a);
}
