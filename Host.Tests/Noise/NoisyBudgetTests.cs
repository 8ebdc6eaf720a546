using MathNet.Numerics.Distributions;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Noise;

/// <summary>
/// The accuracy budget under noise: by default the passes plan with the noisy runs' success, so the budget holds, and the
/// expectation a render prints (always taken with the noisy probabilities) predicts what it measures, also when the passes plan
/// with the ideal ones (<c>--ideal-plan</c>). On scenes, sizes, seeds and rates no part of the model or the budget was tuned on:
/// qornell-16, qornell-32 and depth-complexity-32 at 48x48, seed 7, p = 1e-5, 3e-5, 2e-4 and 1e-3 on the gate-level oracle's model.
/// </summary>
public class NoisyBudgetTests
{
    /// <summary>
    /// A render fails when its measured wrong pixels lie in the upper Poisson tail of its expectation beyond this. The ledger's
    /// expectation errs high (docs/accuracy.md), so a render that keeps its promise fails with probability below 1e-4; over the
    /// twelve renders below, below 1.2e-3.
    /// </summary>
    private const double Tail = 1e-4;

    private static readonly RenderOptions Options = RenderDefaults.Options(48, 48, 7);

    // Each scene once, with its classical reference, whatever the rate: the reference has no noise.
    private static readonly Dictionary<string, (Scene Scene, RgbImage Reference)> Shipped = new[] { "qornell-16", "qornell-32", "depth-complexity-32" }
        .ToDictionary(name => name, name =>
        {
            var scene = SceneLoader.Load(Path.Combine(RepositoryPaths.Scenes, name + ".json"));
            return (scene, Renderer.Render(scene, new EngineSetup(EngineKind.Classical), RenderDefaults.Reference(Options)).Image);
        });

    private static (RenderResult Result, long Wrong) Render(string name, double p, bool idealPlan)
    {
        var (scene, reference) = Shipped[name];
        var result = Renderer.Render(scene, new EngineSetup(EngineKind.Analytic, new QSearchOptions(), Noise: NoiseModel.Depolarizing(p), IdealPlan: idealPlan), Options);
        return (result, ImageError.Between(result.Image, reference).DifferentPixels);
    }

    /// <summary>P(X ≥ <paramref name="measured"/>) for X Poisson with mean <paramref name="expected"/>.</summary>
    private static double UpperTail(long measured, double expected) =>
        measured == 0 ? 1 : expected <= 0 ? 0 : 1 - Poisson.CDF(expected, measured - 1);

    [Theory]
    [InlineData(1e-5)]
    [InlineData(3e-5)]
    [InlineData(2e-4)]
    [InlineData(1e-3)]
    public void TheDefaultPlanKeepsTheBudgetAndItsExpectationUnderNoise(double p)
    {
        foreach (var name in Shipped.Keys)
        {
            var (result, wrong) = Render(name, p, idealPlan: false);
            var budget = result.Budget;
            Assert.False(budget.Exceeded, $"{name}, p = {p}: expected {budget.ExpectedWrongPixels:0.0} wrong pixels against {budget.Allowed:0.0} allowed");
            Assert.True(UpperTail(wrong, budget.ExpectedWrongPixels) >= Tail,
                $"{name}, p = {p}: measured {wrong} wrong pixels against {budget.ExpectedWrongPixels:0.0} expected (upper tail {UpperTail(wrong, budget.ExpectedWrongPixels):0.0e0})");
        }
    }

    [Fact]
    public void AnIdealPlanPrintsTheNoisyExpectationWhichPredictsWhatTheIdealOneCannot()
    {
        // qornell-32 at p = 1e-3, planned with the ideal miss rates: the plan believes it kept the budget, the machine leaves
        // tens of pixels wrong (38 at this seed). The printed expectation, with the noisy probabilities, must hold the measured
        // count in its Poisson tail and say the render is over budget; the plan's own (ideal) expectation must not: the
        // negative control, which fails if the printed figure were taken with the ideal probabilities.
        var (result, wrong) = Render("qornell-32", 1e-3, idealPlan: true);
        var budget = result.Budget;
        var planned = result.Passes.Sum(pass => pass.PlannedWrong);
        Assert.True(planned <= budget.Allowed * (1 + 1e-9), $"the ideal plan expected {planned:0.0} wrong pixels against {budget.Allowed:0.0} allowed");
        Assert.True(wrong > 0 && UpperTail(wrong, planned) < Tail, $"measured {wrong} wrong pixels, the ideal plan's expectation {planned:0.0}");
        Assert.True(UpperTail(wrong, budget.ExpectedWrongPixels) >= Tail, $"measured {wrong} wrong pixels against {budget.ExpectedWrongPixels:0.0} expected under noise");
        Assert.True(budget.Exceeded, $"expected {budget.ExpectedWrongPixels:0.0} against {budget.Allowed:0.0} allowed, not reported over budget");
    }
}
