using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Rendering;

/// <summary>
/// The default pipeline's accuracy budget, <see cref="AccuracyBudget.Target"/> = 0.1 % of pixels wrong in
/// expectation, checked on random scenes it was not tuned on (every <see cref="RandomSceneKind"/>) at 4x4 to
/// 128x128, many seeds, analytic engine, against the classical render.
/// </summary>
public sealed class AccuracyBudgetTests
{
    // Seeds per kind at each size: about 4,800 to 65,000 pixels per size, fewer seeds where images are larger.
    // The 4,000-rectangle scenes only up to 16x16 (each of their rays tests 4,000 primitives classically).
    private static readonly (int Size, int Seeds)[] Plan = [(4, 60), (8, 30), (16, 12), (32, 4), (64, 2), (128, 1)];
    private const int DeepUpTo = 16;

    private static AccuracyConfiguration Default { get; } = AccuracyBenchmark.Standard[0];

    /// <summary>
    /// The statistical check: treating each pixel as wrong independently with probability p, a pipeline with
    /// p = 0.1 % puts more than the Binomial(n, 0.001) upper acceptance bound of wrong pixels in n pixels with
    /// probability below <see cref="StatisticalBounds.FalseFailure"/> / 2 (1e-8 / 2 per size), and with any p below
    /// the budget less often still. Wrong pixels that cluster (one missed occluder seen by several pixels) widen
    /// the spread; the margin below (the default measured about 0.002 % over these scenes, docs/accuracy.md) covers it.
    /// </summary>
    [Theory]
    [InlineData(4)]
    [InlineData(8)]
    [InlineData(16)]
    [InlineData(32)]
    [InlineData(64)]
    [InlineData(128)]
    public void DefaultPipelineKeepsTheBudgetAtEverySize(int size)
    {
        var (wrong, pixels) = WrongPixels(Default, size);
        var (_, high) = StatisticalBounds.BinomialInterval(AccuracyBudget.Target, (int)pixels);
        Assert.True(wrong <= high, $"{size}x{size}: {wrong} of {pixels} pixels wrong; at most {high} expected with a {AccuracyBudget.Target:P1} budget (false-failure {StatisticalBounds.FalseFailure / 2})");
    }

    /// <summary>
    /// The check has the power to fail: the pipeline before the budget (four lattice levels at every size, a ray
    /// ended by the stop rule after one empty search, four rounds) exceeds it at 8x8, where the lower
    /// acceptance bound of Binomial(n, 0.001) is passed (false-failure 1e-8 / 2).
    /// </summary>
    [Fact]
    public void ThePipelineBeforeTheBudgetFailsTheCheck()
    {
        var before = new AccuracyConfiguration("before", (size, seed) => RenderDefaults.CommandLine(size, size, seed) with
        {
            LatticeLevels = RenderDefaults.LatticeLevels, RequiredMisses = 1, Iterations = RenderOptions.DefaultIterations,
        }, new QSearchOptions());
        var (wrong, pixels) = WrongPixels(before, 8);
        var (_, high) = StatisticalBounds.BinomialInterval(AccuracyBudget.Target, (int)pixels);
        Assert.True(wrong > high, $"{wrong} of {pixels} pixels wrong, acceptance bound {high}");
    }

    [Theory]
    [InlineData(4, 4, 0)]
    [InlineData(8, 8, 0)]
    [InlineData(15, 15, 0)]
    [InlineData(16, 16, 1)]
    [InlineData(32, 32, 2)]
    [InlineData(64, 64, 3)]
    [InlineData(128, 128, 4)]
    [InlineData(512, 512, 4)]
    [InlineData(512, 20, 1)]
    public void LatticeLevelsKeepEightPointsAlongTheShorterSide(int width, int height, int levels) =>
        Assert.Equal(levels, RenderDefaults.LatticeLevelsFor(width, height));

    [Fact]
    public void RequiredMissesHoldTheCoarsestRaysToHalfTheBudget()
    {
        // 8x8 without a lattice: 64 rays with nothing to go by, half the budget is 0.032 wrong pixels:
        // 64 · 0.05^2 = 0.16 is too many, 64 · 0.05^3 = 0.008 is within.
        Assert.Equal(3, AccuracyBudget.RequiredMisses(0.05, 8, 8, 0));
        // 128x128 with 4 levels: 64 coarsest rays, allowance 8.2: 64 · 0.05 = 3.2 is within.
        Assert.Equal(1, AccuracyBudget.RequiredMisses(0.05, 128, 128, 4));
        Assert.Equal(1, AccuracyBudget.RequiredMisses(0, 8, 8, 0));
        Assert.Equal(AccuracyBudget.MaxRequiredMisses, AccuracyBudget.RequiredMisses(0.9, 512, 512, 0));
    }

    private static (long Wrong, long Pixels) WrongPixels(AccuracyConfiguration configuration, int size)
    {
        var seeds = Enumerable.Range(1, Plan.Single(p => p.Size == size).Seeds).Select(s => (ulong)s).ToArray();
        var cells = RandomScene.Kinds.Where(k => k != RandomSceneKind.Deep || size <= DeepUpTo)
            .SelectMany(kind => AccuracyBenchmark.Measure(kind, size, seeds, [configuration])).ToArray();
        return (cells.Sum(c => c.WrongPixels), cells.Sum(c => c.Pixels));
    }
}
