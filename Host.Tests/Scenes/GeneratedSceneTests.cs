using QuantumRayTracing.Cli;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Shading;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Scenes;

/// <summary>`scenes generate` is reproducible, and the two light scenes are what docs/scenes.md says they are.</summary>
public class GeneratedSceneTests
{
    private static readonly Scene Temple = Load("temple-32.json");

    [Fact]
    public void ShippedScenesAreTheGeneratorsOutput()
    {
        var marker = GeneratedReport.JsonMarker(ScenesCommand.GenerateCommandText);
        foreach (var (file, builder) in StandardScenes.All())
            Assert.Equal(new GeneratedReport(null, marker).Compose(builder.ToJson()), File.ReadAllText(Path.Combine(RepositoryPaths.Scenes, file)));
    }

    [Fact]
    public void AreaLitBoxIsTheQornellBoxUnderOneCeilingLight()
    {
        var lit = Load("qornell-64-area.json");
        var plain = Load("qornell-64.json");
        Assert.Equal(plain.Rectangles().Select(r => (r.Min, r.Max, r.Material.Name)), lit.Rectangles().Select(r => (r.Min, r.Max, r.Material.Name)));
        Assert.Empty(lit.Lights);
        Assert.Empty(lit.DirectionalLights);
        var light = Assert.Single(lit.AreaLights);
        var ceiling = plain.Rectangles()[1];
        Assert.Equal((1, 1), (light.FlatAxis, ceiling.FlatAxis));
        Assert.Equal(ceiling.PlaneOffset, light.Min.Y);
        Assert.True(light.Min.X > ceiling.Min.X && light.Max.X < ceiling.Max.X && light.Min.Z > ceiling.Min.Z && light.Max.Z < ceiling.Max.Z);
    }

    [Fact]
    public void TempleIsLitOnlyBySunlightWithoutAmbient()
    {
        Assert.Equal(32, Temple.Rectangles().Count);
        Assert.Single(Temple.DirectionalLights);
        Assert.Empty(Temple.Lights);
        Assert.Empty(Temple.AreaLights);
        Assert.Equal(0, Temple.Ambient);
    }

    [Fact]
    public void RaysFromInsideTheTempleLeaveOnlyThroughTheHoleAndNeverMeetFiller()
    {
        // 2,000 directions from points spread through the interior: each either hits a temple surface
        // or, finding nothing, crosses the ceiling's plane (y = 12) inside the hole x 5..11, z 17..23.
        var geometry = new SceneGeometry(Temple);
        var random = new Random(7);
        var escaped = 0;
        for (var i = 0; i < 2000; i++)
        {
            var origin = new Vec3(0.5 + 15 * random.NextDouble(), 0.5 + 11 * random.NextDouble(), 10.5 + 19 * random.NextDouble());
            var direction = new Vec3(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
            var table = RayTable.Build(geometry, new Ray(origin, direction));
            if (BruteForceClosest(table) is { } hit)
            {
                Assert.NotEqual("filler", Temple.Rectangles()[hit].Material.Name);
                continue;
            }
            escaped++;
            Assert.True(direction.Y > 0, $"ray {i} escaped without going up");
            var atCeiling = origin + (12 - origin.Y) / direction.Y * direction;
            Assert.InRange(atCeiling.X, 5, 11);
            Assert.InRange(atCeiling.Z, 17, 23);
        }
        Assert.True(escaped > 0, "some rays leave through the hole");
    }

    [Fact]
    public void SunlightReachesTheFloorOnlyThroughTheHole()
    {
        var geometry = new SceneGeometry(Temple);
        var sun = Temple.DirectionalLights[0];
        var lit = 0;
        for (var x = 0.25; x < 16; x += 0.5)
            for (var z = 10.25; z < 30; z += 0.5)
            {
                var point = new SurfacePoint(0, new Hit(0, 0, 0, new Vec3(x, 0, z)), new Vec3(0, 1, 0), 1);
                var ray = SecondaryRays.TowardsDirectional(point, sun, Temple.Grid)!.Value;
                var table = RayTable.Build(geometry, ray);
                if (table.Marked(table.FullRange).MarkedCount > 0) continue;
                lit++;
                var atCeiling = ray.At((12 - ray.Origin.Y) / ray.Direction.Y);
                Assert.InRange(atCeiling.X, 5, 11);
                Assert.InRange(atCeiling.Z, 17, 23);
            }
        Assert.True(lit > 0, "the sun reaches part of the floor");
    }
}
