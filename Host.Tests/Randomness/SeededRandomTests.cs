using QuantumRayTracing.Randomness;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Randomness;

public class SeededRandomTests
{
    [Fact]
    public void SameSeedGivesSameSequence()
    {
        var a = new SeededRandom(42);
        var b = new SeededRandom(42);
        for (var k = 0; k < 1000; k++) Assert.Equal(a.NextUInt64(), b.NextUInt64());
    }

    [Fact]
    public void DifferentSeedsAndStreamsDiffer()
    {
        var root = new SeededRandom(42);
        Assert.NotEqual(new SeededRandom(43).NextUInt64(), new SeededRandom(42).NextUInt64());
        Assert.NotEqual(root.Fork(1).NextUInt64(), root.Fork(2).NextUInt64());
    }

    [Fact]
    public void ForkDependsOnSeedNotPosition()
    {
        var used = new SeededRandom(7);
        for (var k = 0; k < 10; k++) used.NextUInt64();
        // A stream depends on the seed and its number, never on how much the parent has drawn.
        Assert.Equal(new SeededRandom(7).Fork(5).NextUInt64(), used.Fork(5).NextUInt64());
        Assert.NotEqual(new SeededRandom(8).Fork(5).NextUInt64(), used.Fork(5).NextUInt64());
    }

    [Fact]
    public void NextIntIsUniform()
    {
        var random = new SeededRandom(3);
        const int cells = 7, samples = 70_000;
        var counts = StatisticalBounds.Histogram(Enumerable.Range(0, samples).Select(_ => random.NextInt(cells)), cells);
        StatisticalBounds.AssertFits(counts, Enumerable.Repeat(1.0 / cells, cells).ToArray(), "NextInt(7)");
    }

    [Fact]
    public void NextIntRangeIsInclusive()
    {
        var random = new SeededRandom(9);
        var seen = Enumerable.Range(0, 2000).Select(_ => random.NextInt(1, 3)).ToHashSet();
        Assert.Equal([1, 2, 3], seen.Order());
    }
}
