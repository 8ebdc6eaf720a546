using QuantumRayTracing.Randomness;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Shading;

namespace QuantumRayTracing.Tests.Shading;

/// <summary>The Monte Carlo samples of area lights and VPLs: strata, orientation, and the cosine-weighted density.</summary>
public class SamplingTests
{
    [Theory]
    [InlineData(1, 1, 1)]
    [InlineData(4, 2, 2)]
    [InlineData(7, 7, 1)]
    [InlineData(12, 4, 3)]
    [InlineData(32, 8, 4)]
    [InlineData(512, 32, 16)]
    public void CountsSplitIntoTheSquarestGrid(int count, int columns, int rows) =>
        Assert.Equal((columns, rows), Strata.Split(count));

    [Fact]
    public void EverySampleOfAnAreaLightLiesInItsOwnCell()
    {
        // 32 samples on an 8 x 2 light in the plane y = 5: 8 columns along x (the longer side), 4 rows along z.
        var light = new AreaLight(new Vec3(1, 5, 3), new Vec3(9, 5, 5), 1, new Vec3(1, 1, 1));
        Assert.Equal((8, 4), AreaLightSampler.Cells(light, 32));
        var cells = new HashSet<(int, int)>();
        for (var s = 0; s < 32; s++)
        {
            var p = AreaLightSampler.Sample(light, s, 32, new SeededRandom((ulong)s));
            Assert.Equal(5, p.Y);
            var (column, row) = ((int)Math.Floor(p.X - 1), (int)Math.Floor((p.Z - 3) / 0.5));
            Assert.Equal((s % 8, s / 8), (column, row));
            cells.Add((column, row));
        }
        Assert.Equal(32, cells.Count);
    }

    [Fact]
    public void TheLongerSideGetsTheMoreCells()
    {
        var tall = new AreaLight(new Vec3(0, 0, 2), new Vec3(1, 6, 2), 2, new Vec3(1, 1, 1));
        Assert.Equal((2, 4), AreaLightSampler.Cells(tall, 8));
    }

    [Fact]
    public void CosineWeightedDirectionsHaveMeanCosineTwoThirds()
    {
        // Density cos θ / π: E[cos θ] = 2/3, sd √(1/2 − 4/9) ≈ 0.236; over 20,000 directions the standard
        // error is 0.0017, so the tolerance 0.01 is 6 standard errors (the seed is fixed anyway).
        var normal = new Vec3(0, 0, -1);
        var cosines = Enumerable.Range(0, 20_000)
            .Select(i => CosineHemisphere.Direction(normal, 0, 1, new SeededRandom(1).Fork((ulong)i)))
            .Select(d =>
            {
                Assert.Equal(1, d.Length, 12);
                return d.Dot(normal);
            })
            .ToArray();
        Assert.All(cosines, c => Assert.True(c >= 0));
        Assert.Equal(2.0 / 3, cosines.Average(), 0.01);
    }

    [Fact]
    public void DirectionsOfOneStratumStayInItsPartOfTheHemisphere()
    {
        // Of 4 directions about +y, index 3 lies in cell (1, 1): φ in [π, 2π) (z ≤ 0) and sin²θ in [1/2, 1).
        for (var i = 0; i < 200; i++)
        {
            var d = CosineHemisphere.Direction(new Vec3(0, 1, 0), 3, 4, new SeededRandom((ulong)i));
            Assert.True(d.Z <= 1e-12);
            Assert.InRange(1 - d.Y * d.Y, 0.5 - 1e-12, 1);
        }
    }
}
