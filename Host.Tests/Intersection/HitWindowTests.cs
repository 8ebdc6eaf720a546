using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Tests.Intersection;

/// <summary>The (depth, id) windows of docs/rendering.md, checked on hand-picked pairs.</summary>
public class HitWindowTests
{
    [Theory]
    [InlineData(3, 0, true)]   // at near
    [InlineData(2, 0, false)]  // below near
    [InlineData(9, 7, true)]   // at far, largest id
    [InlineData(10, 0, false)] // past far
    public void RangeIsNearToFarInclusiveForEveryId(int depth, int id, bool accepted) =>
        Assert.Equal(accepted, HitWindow.Range(3, 9, 8).Accepts(depth, id));

    [Fact]
    public void CloserStrictAcceptsEqualDepthWithSmallerId()
    {
        // Current best (depth 6, id 4).
        var window = HitWindow.Closer(1, 6, 4, TieBreak.Strict);
        Assert.True(window.Accepts(5, 9));  // closer, any id
        Assert.True(window.Accepts(6, 3));  // equal depth, smaller id
        Assert.True(window.Accepts(6, 0));
        Assert.False(window.Accepts(6, 4)); // the best itself
        Assert.False(window.Accepts(6, 5)); // equal depth, larger id
        Assert.False(window.Accepts(7, 0)); // farther
        Assert.False(window.Accepts(0, 0)); // before near
    }

    [Fact]
    public void CloserRandomRejectsEqualDepth()
    {
        var window = HitWindow.Closer(1, 6, 4, TieBreak.Random);
        Assert.True(window.Accepts(5, 9));
        Assert.True(window.Accepts(1, 0));
        Assert.False(window.Accepts(6, 3));
        Assert.False(window.Accepts(6, 0));
        Assert.False(window.Accepts(7, 0));
        Assert.False(window.Accepts(0, 2));
    }
}
