using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Passes;

/// <summary>The round loop every pass shares: which rays it searches, in which order, and with which table.</summary>
public class IteratedSearchTests
{
    private static readonly Scene Qornell8 = Load("qornell-8.json");

    /// <summary>More rays than one block, so the next block's tables are built while a block is observed.</summary>
    private const int Rays = IteratedSearch.BlockSize * 2 + 37;

    [Fact]
    public void SearchesEveryUnsettledRayOnceInOrderWithItsOwnTable()
    {
        using var search = new ClassicalHitSearch();
        var geometry = new SceneGeometry(Qornell8);
        var rays = CameraRays.For(Qornell8.Camera, 160, 128);
        Assert.True(rays.Length > Rays);
        var observed = new List<int>();
        var metrics = IteratedSearch.Run("test", search, geometry, rays[..Rays], 3, (_, table) => table.FullRange, (i, table, outcome) =>
        {
            // The table handed with ray i is ray i's, and the certain answer is the brute-force one.
            Assert.Equal(rays[i], table.Ray);
            Assert.Equal(RayTable.Build(geometry, rays[i]).BestAccepted(table.FullRange), outcome.Primitive);
            observed.Add(i);
            return true;
        }, null, settled: i => i % 3 == 0);
        var unsettled = Enumerable.Range(0, Rays).Where(i => i % 3 != 0).ToArray();
        Assert.Equal(unsettled, observed);
        Assert.Equal(1, metrics.Iterations);
        Assert.Equal((long)unsettled.Length * geometry.Count, metrics.TableRows);
    }

    [Fact]
    public void APassWithoutRaysRunsNoRound()
    {
        // A lattice level or a specular pass may have no ray at all (a scene without mirrors).
        using var search = new ClassicalHitSearch();
        var geometry = new SceneGeometry(Qornell8);
        var metrics = IteratedSearch.Run("empty", search, geometry, Array.Empty<Ray>(), 2, (_, table) => table.FullRange,
            (_, _, _) => throw new InvalidOperationException("no ray to observe"), null, settled: _ => false);
        Assert.Equal(0, metrics.Iterations);
        Assert.Equal(0, metrics.Rays);
        Assert.Equal(default, metrics.Cost);
    }
}
