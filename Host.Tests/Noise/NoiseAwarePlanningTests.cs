using QuantumRayTracing.Engines;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Noise;

/// <summary>Passes that plan with the noisy machine's success probabilities (`render` under a noise model, unless <c>--ideal-plan</c>).</summary>
public class NoiseAwarePlanningTests
{
    private static readonly Scene Qornell = SceneLoader.Load(Path.Combine(RepositoryPaths.Scenes, "qornell-64.json"));

    [Fact]
    public void NoisyRunsRaiseQSearchsMissRateAndTheNoiselessOnesKeepIt()
    {
        var schedule = new QSearchSchedule(64);
        var approximation = EngineFactory.Approximation(NoiseOracle.GateLevel, Qornell);
        var ideal = FalseNegativeRate.QSearchExact(schedule, 1);
        Assert.Equal(ideal, FalseNegativeRate.QSearchExact(schedule, 1, approximation.NoisySuccess(NoiseModel.None)), 12);
        // At p = 1e-3 a gate-level iteration at N = 64 survives with F of about 0.002 (docs/noise.md): each run with r ≥ 1 reads a
        // nearly uniform index, so finding the one marked row costs about N/t runs, and the schedule's few runs miss it mostly.
        var noisy = FalseNegativeRate.QSearchExact(schedule, 1, approximation.NoisySuccess(NoiseModel.Depolarizing(1e-3)));
        Assert.True(noisy > 0.5 && noisy > 10 * ideal, $"noisy miss {noisy}, ideal {ideal}");
    }

    [Fact]
    public void UnderHeavyNoiseTheAwareRenderSettlesClassicallyAndKeepsEveryPixel()
    {
        // qornell-64 at 32x32, p = 1e-3 on the gate-level oracle's model, seed fixed: the render that plans with ideal miss rates
        // stops searches that would have hit and loses pixels; the aware one finds every noisy search dearer than N tests and
        // settles every ray classically: brute force's Int/Ray and its image.
        var options = NoisyRenderBenchmark.Defaults(32);
        var classical = RenderMeasurement.Reference(Qornell, options);
        var noise = NoiseModel.Depolarizing(1e-3);
        var blind = RenderMeasurement.Run(Qornell, new EngineSetup(EngineKind.Analytic, new QSearchOptions(), Noise: noise, IdealPlan: true), options, classical);
        var aware = RenderMeasurement.Run(Qornell, new EngineSetup(EngineKind.Analytic, new QSearchOptions(), Noise: noise), options, classical);

        Assert.True(blind.Error.DifferentPixels > 0, "the noise-blind render should lose pixels at p = 1e-3");
        Assert.Equal(0, aware.Error.DifferentPixels);
        Assert.Equal(64.0, aware.Result.Total.PerRayConservative, 9);
    }
}
