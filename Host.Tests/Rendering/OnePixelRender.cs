using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Rendering;

/// <summary>Hand-computed radiance checks: a scene rendered classically at one pixel, compared to 12 digits.</summary>
internal static class OnePixelRender
{
    public static RenderResult Render(Scene scene)
    {
        using var search = new ClassicalHitSearch();
        return SceneRenderer.Render(scene, search, new RenderOptions(1, 1));
    }

    public static void AssertClose(Vec3 expected, Vec3 actual)
    {
        Assert.Equal(expected.X, actual.X, 12);
        Assert.Equal(expected.Y, actual.Y, 12);
        Assert.Equal(expected.Z, actual.Z, 12);
    }
}
