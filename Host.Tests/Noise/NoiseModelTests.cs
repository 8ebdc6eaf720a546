using QuantumRayTracing.Cli;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Intersection;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Tests.Cli;

namespace QuantumRayTracing.Tests.Noise;

public sealed class NoiseModelTests : IDisposable
{
    private static readonly string Scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");

    private readonly ScratchDirectory _scratch = new("qrt-noise-");

    public void Dispose() => _scratch.Dispose();

    [Fact]
    public void OneProbabilityIsSplitEvenlyOverXYZ()
    {
        Assert.Equal((0.01, 0.01, 0.01), NoiseModel.ParsePauli("0.03", out _)!.Value);
        Assert.Equal((0.001, 0.0, 0.002), NoiseModel.ParsePauli("0.001, 0, 0.002", out _)!.Value);
        Assert.Equal(0.03, NoiseModel.Depolarizing(0.03).PerGate, 12);
    }

    [Fact]
    public void TheNoiseOptionsMakeOneModel()
    {
        Assert.Same(NoiseModel.None, NoiseModel.Of(null, 0));
        var lossOnly = NoiseModel.Of(null, 0.1);
        Assert.Equal((0.0, 0.0, 0.0, 0.1), (lossOnly.Px, lossOnly.Py, lossOnly.Pz, lossOnly.QubitLoss));
        var both = NoiseModel.Of("0.001,0,0.002", 0.2);
        Assert.Equal((0.001, 0.0, 0.002, 0.2), (both.Px, both.Py, both.Pz, both.QubitLoss));
        Assert.Throws<ArgumentException>(() => NoiseModel.Of("0.1,0.1", 0));
    }

    [Theory]
    [InlineData("-0.1", "not a probability")]
    [InlineData("NaN", "not a probability")]
    [InlineData("1.5", "not a probability")]
    [InlineData("0.5,0.4,0.2", "exceeds 1")]
    [InlineData("0.1,-0.1,0", "py = -0.1 is negative")]
    [InlineData("0.1,0.1", "neither one probability")]
    [InlineData("x", "'x' is not a number")]
    public void BadNoiseIsRejectedWithItsReason(string text, string reason)
    {
        Assert.Null(NoiseModel.ParsePauli(text, out var problem));
        Assert.Contains(reason, problem);
    }

    [Theory]
    [InlineData(-0.01)]
    [InlineData(1.0)]
    [InlineData(double.NaN)]
    public void LossOutsideItsRangeIsRejected(double loss)
    {
        Assert.NotNull(NoiseModel.LossProblem(loss));
        Assert.Throws<ArgumentException>(() => new NoiseModel(0, 0, 0, loss));
    }

    [Fact]
    public void DescriptionNamesTheModel()
    {
        Assert.Equal("noiseless (ideal gates)", NoiseModel.None.Description());
        Assert.Contains("p = 0.003 per gate", NoiseModel.Depolarizing(0.003).Description());
        Assert.Contains("px = 0.001, py = 0, pz = 0.002", new NoiseModel(0.001, 0, 0.002).Description());
        Assert.Contains("qubit loss 0.01", new NoiseModel(0, 0, 0, 0.01).Description());
    }

    [Theory]
    [InlineData("analytic", "--noise", "-1", "--noise: P = -1 is not a probability")]
    [InlineData("analytic", "--noise", "0.4,0.4,0.4", "--noise: px + py + pz = 1.2 exceeds 1")]
    [InlineData("analytic", "--qubit-loss", "1", "--qubit-loss: 1 lies outside [0, 1)")]
    public void BadNoiseOptionsAreUsageErrors(string engine, string option, string value, string message)
    {
        var (code, error) = ConsoleCapture.Run("render", Scene, "-e", engine, "--size", "4", option, value, "-o", _scratch.File("x.png"));
        Assert.Equal(1, code);
        Assert.Contains(message, error);
        Assert.Single(error.Trim().Split('\n'));
        Assert.Empty(_scratch.FileNames());
    }

    [Theory]
    [InlineData("classical", "--noise", "0.01", "--noise: the classical engine runs no quantum circuit")]
    [InlineData("analytic", "--qubit-loss", "0.01", "--qubit-loss: the analytic engine does not model qubit loss")]
    [InlineData("gate", "--qubit-loss", "0.01", "--qubit-loss: the gate engine cannot simulate qubit loss")]
    public void NoiseAnEngineCannotRunIsRefusedBeforeRendering(string engine, string option, string value, string message)
    {
        var (code, error) = ConsoleCapture.Run("render", Scene, "-e", engine, "--size", "4", option, value, "-o", _scratch.File("x.png"));
        Assert.NotEqual(0, code);
        Assert.Contains(message, error);
        Assert.Empty(_scratch.FileNames());
    }

    [Fact]
    public void NoisyAnalyticRenderIsByteIdenticalForTheSameSeed()
    {
        string Render(string name, string seed)
        {
            var output = _scratch.File(name);
            Assert.Equal(0, ConsoleCapture.Run(["render", Scene, "-e", "analytic", "--size", "16", "--noise", "0.02", "--seed", seed, "-o", output]).Code);
            return output;
        }
        var first = File.ReadAllBytes(Render("a.png", "7"));
        Assert.Equal(first, File.ReadAllBytes(Render("b.png", "7")));
    }

    [Fact]
    public void NoiseCostsTheAnalyticRenderMisses()
    {
        // QSearch verifies every candidate, so noise never makes a false hit; it lowers the success
        // probability, and the termination rule then ends searches that would have hit. At p = 0.02 most
        // runs over 32 primitives read a random index (P(marked) 0.06 against the ideal 0.999 at r = 4, t = 1): the ideal
        // render is exact, the noisy one is not. 32 primitives and 8x8 pixels, not 64 and 16x16: the noisy lookup run at
        // N = 64 is evolved as an 8 MB density matrix per marked count, most of the test's time, and the claim needs neither.
        double Nrmse(NoiseModel noise)
        {
            var scene = TestScenes.Load("qornell-32.json");
            using var search = EngineFactory.CreateSearch(EngineKind.Analytic, new SeededRandom(3), 1, new QSearchOptions(), noise: noise);
            using var classical = new ClassicalHitSearch();
            var options = new RenderOptions(8, 8);
            return ImageError.Between(SceneRenderer.Render(scene, search, options).Image, SceneRenderer.Render(scene, classical, options).Image).Nrmse;
        }
        Assert.Equal(0, Nrmse(NoiseModel.None));
        Assert.True(Nrmse(NoiseModel.Depolarizing(0.02)) > 0.1);
    }
}
