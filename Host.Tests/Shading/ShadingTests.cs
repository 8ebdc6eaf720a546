using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Shading;
using static QuantumRayTracing.Tests.Intersection.TestScenes;
using static QuantumRayTracing.Tests.Rendering.OnePixelRender;

namespace QuantumRayTracing.Tests.Shading;

/// <summary>
/// Whitted shading, shadow rays and mirror rays on hand-built points, and 1x1 renders whose single
/// pixel is computed here from the formulas: albedo · (ambient + Σ I · cos θ / d²), gamma 1/2.2, 8 bits.
/// </summary>
public class ShadingTests
{
    // The floor y = 0 (albedo 0.5, 0.6, 0.8) seen straight down from (4, 8, 4): a 1x1 image's ray hits (4, 0, 4).
    private const string LookDown = """{ "position": [4, 8, 4], "lookAt": [4, 0, 4], "up": [0, 0, 1] }""";
    private static readonly string Floor = Rect(0, 0, 0, 8, 0, 8);
    private static readonly string Blocker = Rect(5, 2, 3, 6, 2, 5); // on the segment to the light, beside the camera ray

    // Light at (7, 4, 4), intensity 25: from (4, 0, 4) the light is at (3, 4, 0), d² = 25, cos θ = 4/5 against
    // the normal +y, so I · cos θ / d² = 25 · 0.8 / 25 = 0.8; with ambient 0.1 the irradiance is 0.9.
    private const string OneLight = """[ { "position": [7, 4, 4], "intensity": [25, 25, 25] } ]""";
    private static readonly Vec3 Lit = new(0.5 * 0.9, 0.6 * 0.9, 0.8 * 0.9);
    private static readonly Vec3 Unlit = new(0.5 * 0.1, 0.6 * 0.1, 0.8 * 0.1);

    private static SurfacePoint FloorPoint() =>
        new(0, new Hit(0, 8, 8, new Vec3(4, 0, 4)), new Vec3(0, 1, 0), 1);

    private static byte Byte(double linear) => (byte)Math.Round(Math.Min(1, Math.Pow(linear, 1 / 2.2)) * 255, MidpointRounding.AwayFromZero);

    private static (byte, byte, byte) Pixel(Vec3 radiance) => (Byte(radiance.X), Byte(radiance.Y), Byte(radiance.Z));

    [Fact]
    public void RadianceIsAlbedoTimesAmbientPlusVisibleLights()
    {
        var scene = With(4, 0, [Floor], LookDown, OneLight, ambient: 0.1);
        AssertClose(Lit, WhittedShading.Radiance(scene, FloorPoint(), _ => true));
        AssertClose(Unlit, WhittedShading.Radiance(scene, FloorPoint(), _ => false));
    }

    [Fact]
    public void RenderedPixelIsLitWhenTheLightIsVisible()
    {
        var result = Render(With(4, 0, [Floor], LookDown, OneLight, ambient: 0.1));
        Assert.Equal(Pixel(Lit), result.Image.GetPixel(0, 0));
        Assert.Equal(1, result.Passes[2].Rays); // one shadow ray
    }

    [Fact]
    public void RenderedPixelIsAmbientOnlyWhenTheLightIsOccluded()
    {
        var result = Render(With(4, 0, [Floor, Blocker], LookDown, OneLight, ambient: 0.1));
        Assert.Equal(Pixel(Unlit), result.Image.GetPixel(0, 0));
        Assert.Equal(1, result.Passes[2].Rays);
    }

    [Theory]
    [InlineData(4, -3, 4)] // below the floor
    [InlineData(9, 0, 4)]  // in the floor's plane: cos θ = 0
    public void LightBehindTheSurfaceSpawnsNoShadowRay(double x, double y, double z)
    {
        var light = new PointLight(new Vec3(x, y, z), new Vec3(25, 25, 25));
        var scene = With(4, 0, [Floor], LookDown, $$"""[ { "position": [{{x}}, {{y}}, {{z}}], "intensity": [25, 25, 25] } ]""", ambient: 0.1);
        Assert.Null(SecondaryRays.Shadow(FloorPoint(), light));
        var result = Render(scene);
        Assert.Equal(0, result.Passes[2].Rays);
        Assert.Equal(Pixel(Unlit), result.Image.GetPixel(0, 0));
    }

    [Fact]
    public void ShadowRayIsTheSegmentToTheLight()
    {
        var scene = With(4, 0, [Floor], LookDown, OneLight, ambient: 0.1);
        var shadow = SecondaryRays.Shadow(FloorPoint(), scene.Lights[0]);
        Assert.NotNull(shadow);
        var ray = shadow.Value;
        Assert.Equal(new Vec3(4, 0, 4), ray.Origin);
        Assert.Equal(new Vec3(3, 4, 0), ray.Direction);
        Assert.Equal(1.0, ray.MaxDistance);
        Assert.Equal(0, ray.ExcludedPrimitive);
    }

    [Fact]
    public void FacingNormalPointsBackAtTheRay()
    {
        var scene = With(4, 0, Rect(0, 0, 0, 8, 0, 8), Rect(9, 0, 0, 9, 8, 8), Rect(0, 0, 8, 8, 8, 8));
        var origin = new Vec3(1, 1, 1);
        Assert.Equal(new Vec3(0, 1, 0), SurfacePoint.FacingNormal(new Ray(origin, new Vec3(0.1, -1, 0)), scene.Primitives[0]));
        Assert.Equal(new Vec3(0, -1, 0), SurfacePoint.FacingNormal(new Ray(origin, new Vec3(0.1, 1, 0)), scene.Primitives[0]));
        Assert.Equal(new Vec3(-1, 0, 0), SurfacePoint.FacingNormal(new Ray(origin, new Vec3(1, 0.2, 0)), scene.Primitives[1]));
        Assert.Equal(new Vec3(0, 0, 1), SurfacePoint.FacingNormal(new Ray(origin, new Vec3(0, 0, -2)), scene.Primitives[2]));
    }

    [Fact]
    public void SpecularRayReflectsAboutTheFacingNormalAndLeavesTheMirror()
    {
        var scene = With(4, 0, Rect(9, 0, 0, 9, 8, 8), Rect(0, 0, 0, 8, 0, 8, "mirror"));
        // Down onto the floor mirror (id 1): normal +y, (1, −2, 3) → (1, 2, 3).
        var down = new Ray(new Vec3(1, 4, 1), new Vec3(1, -2, 3));
        var floorHit = new Hit(1, 4, 2, down.At(2));
        var reflected = SecondaryRays.Specular(down, SurfacePoint.Of(0, down, floorHit, scene.Primitives[1], 0.5));
        Assert.Equal(new Vec3(1, 2, 3), reflected.Direction);
        Assert.Equal(new Vec3(3, 0, 7), reflected.Origin);
        Assert.Equal(1, reflected.ExcludedPrimitive);
        Assert.Equal((0, Ray.Unbounded, double.PositiveInfinity), (reflected.Near, reflected.Far, reflected.MaxDistance));
        // Onto the wall x = 9 (id 0) from the +x side: normal +x, (−1, 2, 0.5) → (1, 2, 0.5).
        var back = new Ray(new Vec3(11, 1, 1), new Vec3(-1, 2, 0.5));
        var wallHit = new Hit(0, 2, 2, back.At(2));
        var bounced = SecondaryRays.Specular(back, SurfacePoint.Of(0, back, wallHit, scene.Primitives[0], 0.5));
        Assert.Equal(new Vec3(1, 2, 0.5), bounced.Direction);
        Assert.Equal(0, bounced.ExcludedPrimitive);
    }

    [Fact]
    public void MirrorPixelMixesItsOwnShareAndTheReflectedSurface()
    {
        // From (1, 4, 4) towards (3, 2, 4): the floor mirror (id 0: diffuse 0.2, mirror 0.5) at (5, 0, 4); the
        // reflection (1, 1, 0) meets the grey wall x = 9 (id 1, albedo 0.8) at (9, 4, 4). Ambient 0.2, no lights:
        // (1 − 0.5) · 0.2 · 0.2 + 0.5 · (1 − 0) · 0.8 · 0.2 = 0.02 + 0.08 = 0.1 in every channel.
        var scene = With(4, 0, [Rect(0, 0, 0, 8, 0, 8, "mirror"), Rect(9, 0, 0, 9, 8, 8, "grey")],
            """{ "position": [1, 4, 4], "lookAt": [3, 2, 4] }""", ambient: 0.2);
        var result = Render(scene);
        Assert.Equal(Pixel(new Vec3(0.1, 0.1, 0.1)), result.Image.GetPixel(0, 0));
        Assert.Equal((1L, 1L, 0L), (result.Passes[0].Rays, result.Passes[1].Rays, result.Passes[2].Rays));
    }
}
