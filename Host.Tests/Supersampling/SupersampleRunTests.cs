using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Tests.Supersampling;

/// <summary>
/// <see cref="SupersampleRun"/> called as a library, without the command line: the files it writes hold the images it
/// returns, its figures are those of the images, the same seed gives the same bytes, Monte Carlo estimates scatter as
/// the binomial says, and a setting the engine cannot run stops the run before any work or file.
/// </summary>
public sealed class SupersampleRunTests : IDisposable
{
    private static readonly string Qornell8 = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");

    private readonly ScratchDirectory _scratch = new("qrt-supersample-run-");

    public void Dispose() => _scratch.Dispose();

    private SupersampleRunSettings Settings(SupersampleSettings method, string output, ulong seed = 1, int size = 16, EngineKind engine = EngineKind.Analytic, NoiseModel? noise = null) =>
        new(method, null, Qornell8, (size, size), new EngineSetup(engine, new QuantumRayTracing.Search.QSearchOptions(), QuantumRayTracing.Bridge.BridgePool.DefaultWorkers, Noise: noise), seed, _scratch.File(output), TableDirectory: _scratch.File("tables"));

    [Fact]
    public void MonteCarloEstimatesScatterAsBinomialsAroundTheExactMeans()
    {
        const long queries = 64;
        var run = SupersampleRun.Run(Settings(new SupersampleSettings(SupersampleMethod.Mc, 4, queries), "mc.png"));
        var (input, estimates) = (run.Input, run.Estimate.Estimates);
        Assert.False(input.IsGrey);

        // Each estimate is heads / Q of Binomial(Q, mean): unbiased in sum, with variance mean(1 - mean) / Q per item.
        var (bias, squares, variance) = (0.0, 0.0, 0.0);
        for (var p = 0; p < input.Pixels; p++)
            for (var c = 0; c < 3; c++)
            {
                var mean = input.Mean(p, c);
                bias += estimates[3 * p + c] - mean;
                squares += Math.Pow(estimates[3 * p + c] - mean, 2);
                variance += mean * (1 - mean) / queries;
            }
        Assert.True(variance > 0, "the scene has no pixel with a mean strictly between 0 and 1");
        // z = 5: a false failure about once in 1.7 million runs; the seed is fixed, so a failure is a biased estimator.
        Assert.InRange(bias / Math.Sqrt(variance), -5, 5);
        // 768 items: the summed squares spread by about 5% of their expectation; ±30% is six of those.
        Assert.InRange(squares / variance, 0.7, 1.3);
        Assert.Equal(queries * 3 * 16 * 16, run.Figures.TotalQueries);
    }

    [Fact]
    public void WritesTheImagesItReturnsAndCountsTheirExactPixels()
    {
        var settings = Settings(new SupersampleSettings(SupersampleMethod.Qss, 4), "qss.png");
        var run = SupersampleRun.Run(settings);

        Assert.Equal(["qss-confidence.png", "qss.png"], _scratch.FileNames());
        Assert.Equal(settings.Files, run.Figures.Written);
        Assert.Equal(run.Estimate.Image.Pixels.ToArray(), ImageReader.Read(settings.Files[0]).Pixels.ToArray());
        Assert.Equal(run.Estimate.ConfidenceMap!.Pixels.ToArray(), ImageReader.Read(settings.Files[1]).Pixels.ToArray());

        // Zero-error pixels, counted here against the exact averages quantised to 8 bits.
        var (output, ideal) = (run.Estimate.Image, run.Input.Ideal());
        var exact = 0;
        for (var y = 0; y < output.Height; y++)
            for (var x = 0; x < output.Width; x++)
                exact += output.GetPixel(x, y) == ideal.GetPixel(x, y) ? 1 : 0;
        Assert.Equal(exact, run.Figures.Error.ExactPixels);
        Assert.InRange(exact, 1, 16 * 16 - 1);

        // Bit-plane QSS with 16 subpixels and 4 counter bits: 2^5 - 1 queries per plane, 8 planes.
        Assert.Equal(31 * 8, run.Figures.QueriesPerChannel);
        Assert.Equal(((4 * 16, 4 * 16), (16, 16), 4), ((run.Figures.InputWidth, run.Figures.InputHeight), (run.Figures.OutputWidth, run.Figures.OutputHeight), run.Figures.Subpixels));
        Assert.Equal(16, run.Figures.LookupTableReadouts);
        Assert.NotNull(run.Figures.InputRenderTime);
        Assert.Equal(RunPlace.NoBridges, run.RanOn);
    }

    [Fact]
    public void TheSameSeedGivesTheSameBytesAndAnotherSeedOthers()
    {
        var method = new SupersampleSettings(SupersampleMethod.QCoin, 4);
        SupersampleRun.Run(Settings(method, "a.png", seed: 7));
        SupersampleRun.Run(Settings(method, "b.png", seed: 7));
        SupersampleRun.Run(Settings(method, "c.png", seed: 8));
        Assert.Equal(File.ReadAllBytes(_scratch.File("a.png")), File.ReadAllBytes(_scratch.File("b.png")));
        Assert.NotEqual(File.ReadAllBytes(_scratch.File("a.png")), File.ReadAllBytes(_scratch.File("c.png")));
    }

    [Fact]
    public void ThePlanComesBeforeTheEstimatesAndTheLookupTableIsBuiltOnce()
    {
        var progress = new RecordingProgress();
        var plans = new List<(SupersamplePlan Plan, IReadOnlyList<string> StartedBefore)>();
        var settings = Settings(new SupersampleSettings(SupersampleMethod.Qss, 4), "first.png", size: 4);
        SupersampleRun.Run(settings, progress, plan => plans.Add((plan, progress.Started.ToArray())));
        var again = SupersampleRun.Run(settings with { Output = _scratch.File("second.png") }, null, plan => plans.Add((plan, [])));

        Assert.Equal(2, plans.Count);
        Assert.Equal(["classical render"], plans[0].StartedBefore);
        Assert.Equal(["classical render", "analytic"], progress.Started);
        Assert.Equal(progress.Started.Count, progress.Finished);
        var (first, second) = (plans[0].Plan, plans[1].Plan);
        Assert.False(first.TableWasCached);
        Assert.True(second.TableWasCached);
        Assert.StartsWith(_scratch.File("tables"), first.TablePath);
        Assert.True(File.Exists(first.TablePath));
        Assert.Equal(again.Figures.QueriesPerChannel, second.Estimator.Queries);
    }

    [Fact]
    public void QubitLossOnTheAnalyticEngineStopsTheRunBeforeAnyWork()
    {
        var progress = new RecordingProgress();
        var settings = Settings(new SupersampleSettings(SupersampleMethod.Mc, 4), "loss.png", noise: new NoiseModel(0, 0, 0, 0.1));
        var error = Assert.Throws<UserError>(() => SupersampleRun.Run(settings, progress, _ => Assert.Fail("no plan for a run that cannot start")));
        Assert.StartsWith("--qubit-loss:", error.Message);
        Assert.Empty(progress.Started);
        Assert.Empty(_scratch.FileNames());
    }

    [Fact]
    public void TheFullStateEngineRefusesALargeOutputBeforeTheSceneIsRendered()
    {
        var progress = new RecordingProgress();
        var settings = Settings(new SupersampleSettings(SupersampleMethod.Mc, 4), "large.png", size: 17, engine: EngineKind.FullState);
        var error = Assert.Throws<UserError>(() => SupersampleRun.Run(settings, progress));
        Assert.Contains($"at most {SupersampleRunSettings.MaxFullStatePixels} output pixels", error.Message);
        Assert.Empty(progress.Started);
        Assert.Empty(_scratch.FileNames());
    }

    private sealed class RecordingProgress : IRunProgress
    {
        public List<string> Started { get; } = [];

        public int Finished { get; private set; }

        public IRenderProgress Start(string label)
        {
            Started.Add(label);
            return new NoProgress();
        }

        public void Finish() => Finished++;
    }

    private sealed class NoProgress : IRenderProgress
    {
        public void Report(string stage, double done)
        {
        }
    }
}
