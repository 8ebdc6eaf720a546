using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Rendering;

/// <summary>Camera rays computed when read (what a render holds) against the stored array, and their geometry.</summary>
public class CameraRaysTests
{
    private static readonly Camera Qornell = Load("qornell-8.json").Camera;

    [Theory]
    [InlineData(1, 1)]
    [InlineData(7, 5)]
    [InlineData(64, 48)]
    public void ComputedRaysAreTheStoredRaysBitForBit(int width, int height)
    {
        var stored = CameraRays.For(Qornell, width, height);
        var computed = CameraRays.Computed(Qornell, width, height);
        Assert.Equal(stored.Length, computed.Count);
        for (var i = 0; i < stored.Length; i++)
        {
            Assert.Equal(stored[i], computed[i]);
            Assert.Equal(stored[i], computed[i]); // read twice: the same ray each time
        }
        Assert.Equal(stored, computed.ToArray());
    }

    [Fact]
    public void PixelsMirroredAcrossTheCentreGetMirroredDirections()
    {
        // Qornell's camera looks along +z with y up: pixel (x, y) and (w−1−x, h−1−y) differ only in the signs of x and y.
        var (width, height) = (6, 4);
        var rays = CameraRays.Computed(Qornell, width, height);
        var (a, b) = (rays[1 * width + 0], rays[(height - 2) * width + width - 1]);
        Assert.Equal(a.Direction.X, -b.Direction.X, 12);
        Assert.Equal(a.Direction.Y, -b.Direction.Y, 12);
        Assert.Equal(a.Direction.Z, b.Direction.Z, 12);
        Assert.True(a.Direction.X < 0 && a.Direction.Y > 0, "the top left pixel looks left and up");
    }

    [Fact]
    public void AComputedListRefusesAnIndexOutsideIt()
    {
        var list = new ComputedList<int>(3, i => i * i);
        Assert.Equal([0, 1, 4], list);
        Assert.Throws<ArgumentOutOfRangeException>(() => list[3]);
        Assert.Throws<ArgumentOutOfRangeException>(() => list[-1]);
    }
}
