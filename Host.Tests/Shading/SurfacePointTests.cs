using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Shading;

namespace QuantumRayTracing.Tests.Shading;

/// <summary>A surface point keeps its unit normal in single precision: every axis normal comes back exactly, any other unit normal to single precision, a vector that is not a unit one is refused.</summary>
public class SurfacePointTests
{
    private static readonly Material Grey = new("grey", new Vec3(0.5, 0.5, 0.5), 0);

    private static readonly Hit AHit = new(3, 7, 2.5, new Vec3(1, 2, 3));

    public static TheoryData<double, double, double> AxisNormals => new()
    {
        { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 },
    };

    [Theory]
    [MemberData(nameof(AxisNormals))]
    public void AnAxisNormalComesBackAsGiven(double x, double y, double z)
    {
        var point = new SurfacePoint(5, AHit, new Vec3(x, y, z), 0.25);
        Assert.Equal(new Vec3(x, y, z), point.Normal);
        Assert.Equal((5, AHit, 0.25), (point.Pixel, point.Hit, point.Weight));
    }

    [Fact]
    public void TheFacingNormalOfEveryRectangleAndSideComesBack()
    {
        // Rectangles flat in x, y and z, seen from both sides.
        Rectangle[] rectangles =
        [
            new(0, new Vec3(4, 0, 0), new Vec3(4, 2, 2), 0, Grey), new(1, new Vec3(0, 4, 0), new Vec3(2, 4, 2), 1, Grey), new(2, new Vec3(0, 0, 4), new Vec3(2, 2, 4), 2, Grey),
        ];
        foreach (var rectangle in rectangles)
            foreach (var direction in new[] { new Vec3(1, 1, 1), new Vec3(-1, -1, -1) })
            {
                var ray = new Ray(Vec3.Zero, direction);
                var point = SurfacePoint.Of(0, ray, AHit, rectangle, 1);
                Assert.Equal(SurfacePoint.FacingNormal(ray, rectangle), point.Normal);
                Assert.True(point.Normal.Dot(direction) < 0, "the normal faces the ray");
            }
    }

    [Fact]
    public void AUnitNormalOffTheAxesComesBackToSinglePrecision()
    {
        var normal = new Vec3(0.6, 0.8, 0);
        var back = new SurfacePoint(0, AHit, normal, 1).Normal;
        Assert.True((back - normal).Length < 1e-7, $"{back} is not {normal}");
        Assert.NotEqual(normal, back);
    }

    [Theory]
    [InlineData(1, 1, 0)]
    [InlineData(0, 0, 0)]
    [InlineData(0, 0, 2)]
    public void ANormalThatIsNotAUnitVectorIsRefused(double x, double y, double z) =>
        Assert.Throws<ArgumentException>(() => new SurfacePoint(0, AHit, new Vec3(x, y, z), 1));
}
