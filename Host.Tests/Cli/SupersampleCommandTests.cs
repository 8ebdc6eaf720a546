using QuantumRayTracing.Cli;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Search;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using QuantumRayTracing.Tests.Output;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>
/// `supersample` through <see cref="CommandLine.Run"/>: exit codes (0 ok, 1 usage, 2 bad input), the one-line
/// errors on standard error, the files it writes, and that it writes nothing when it fails.
/// </summary>
public sealed class SupersampleCommandTests : IDisposable
{
    private static readonly string Scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");

    private readonly ScratchDirectory _scratch = new("qrt-supersample-");

    public void Dispose() => _scratch.Dispose();

    private static (int Code, string Error) Run(params string[] args) => ConsoleCapture.Run(args);

    private string WriteImage(string name, int width, int height, Func<int, int, (byte, byte, byte)> colour)
    {
        var image = new RgbImage(width, height);
        for (var y = 0; y < height; y++)
            for (var x = 0; x < width; x++)
            {
                var (r, g, b) = colour(x, y);
                image.SetPixel(x, y, r, g, b);
            }
        var path = _scratch.File(name);
        PngWriter.Write(image, path);
        return path;
    }

    // 2x2 blocks, each channel of each block black or white: every method's estimate of a mean of 0 or 1 is exact.
    private static (byte, byte, byte) BlackOrWhiteBlocks(int x, int y)
    {
        var block = x / 2 * 7 + y / 2 * 3;
        return ((byte)(block % 2 * 255), (byte)(block / 2 % 2 * 255), (byte)(block / 4 % 2 * 255));
    }

    // Not fae: it estimates f/4 on the rescaled coin, so white (f = 1, angle π/6) is no end of its range and comes out inexact.
    [Theory]
    [InlineData("mc")]
    [InlineData("qcoin")]
    [InlineData("mlae")]
    [InlineData("mlae-noise")]
    [InlineData("iqae")]
    [InlineData("bae")]
    [InlineData("qss-bayes")]
    [InlineData("powerlaw")]
    [InlineData("qss")]
    [InlineData("qss", "--qss-values", "continuous")]
    [InlineData("qss", "--planes", "1")]
    public void EveryMethodReproducesBlackAndWhiteBlocksExactly(string method, params string[] extra)
    {
        var input = WriteImage("in.png", 8, 6, BlackOrWhiteBlocks);
        var output = _scratch.File("out.png");
        var (code, error) = Run(["supersample", "--image", input, "--subpixels", "2", "-m", method, .. extra, "-o", output]);
        Assert.True(code == 0, error);
        var image = ImageReader.Read(output);
        Assert.Equal((4, 3), (image.Width, image.Height));
        for (var y = 0; y < 3; y++)
            for (var x = 0; x < 4; x++)
                Assert.Equal(BlackOrWhiteBlocks(2 * x, 2 * y), image.GetPixel(x, y));
    }

    /// <summary>
    /// Files of other formats made by ImageMagick from the same blocks (Output/Images/make-fixtures.sh) supersample to the
    /// same block colours. Lossless files exactly. The JPEG (quality 95, no chroma subsampling) within 20 levels: its
    /// ringing at the blocks' sharp edges moves subpixels by up to 8 levels (measured on this file), so a block's mean F
    /// is within 8 levels of 0 or 255 and Monte Carlo's 240 flips have a standard deviation of at most
    /// 255 sqrt(F (1 - F) / 240) = 2.9 levels; 8 + 4 of those is 20. Each of the 36 channels then fails by chance with
    /// probability below 1e-4 (the seed is fixed, so the run is the same every time).
    /// </summary>
    [Theory]
    [InlineData("blocks-16bit.png", 0)]
    [InlineData("blocks-palette-interlaced.png", 0)]
    [InlineData("blocks.jpg", 20)]
    public void OtherFormatsSupersampleToTheBlockColours(string file, int tolerance)
    {
        var output = _scratch.File("out.png");
        var (code, error) = Run("supersample", "--image", ImageFixtures.Path(file), "--subpixels", "2", "-m", "mc", "-o", output);
        Assert.True(code == 0, error);
        var image = ImageReader.Read(output);
        Assert.Equal((4, 3), (image.Width, image.Height));
        for (var y = 0; y < 3; y++)
            for (var x = 0; x < 4; x++)
            {
                var (r, g, b) = image.GetPixel(x, y);
                var (er, eg, eb) = BlackOrWhiteBlocks(2 * x, 2 * y);
                var worst = Math.Max(Math.Abs(r - er), Math.Max(Math.Abs(g - eg), Math.Abs(b - eb)));
                Assert.True(worst <= tolerance, $"{file}: output ({x}, {y}) is ({r}, {g}, {b}), expected ({er}, {eg}, {eb}) within {tolerance}");
            }
    }

    [Fact]
    public void BitPlaneQssWritesAGreyConfidenceMapAndMonteCarloNone()
    {
        var input = WriteImage("in.png", 8, 8, (x, y) => ((byte)(x * 30), (byte)(y * 30), (byte)(x * y * 4)));
        Assert.Equal(0, Run("supersample", "--image", input, "--subpixels", "4", "-o", _scratch.File("q.png")).Code);
        var map = ImageReader.Read(_scratch.File("q-confidence.png"));
        Assert.Equal((2, 2), (map.Width, map.Height));
        for (var y = 0; y < 2; y++)
            for (var x = 0; x < 2; x++)
            {
                var (r, g, b) = map.GetPixel(x, y);
                Assert.True(r == g && g == b && r > 0, $"confidence pixel ({x}, {y}) is ({r}, {g}, {b})");
            }
        Assert.Equal(0, Run("supersample", "--image", input, "--subpixels", "4", "-m", "mc", "-o", _scratch.File("m.png")).Code);
        Assert.Equal(["in.png", "m.png", "q-confidence.png", "q.png"], _scratch.FileNames());
    }

    [Fact]
    public void SceneWithOneSubpixelIsTheClassicalRender()
    {
        // One binary subpixel per plane (N = 1, t = 1) reads its hit count with certainty: QSS returns the render itself.
        var output = _scratch.File("s.png");
        var (code, error) = Run("supersample", "--scene", Scene, "--size", "6x4", "--subpixels", "1", "-o", output);
        Assert.True(code == 0, error);
        using var classical = new ClassicalHitSearch();
        var expected = SceneRenderer.Render(Load("qornell-8.json"), classical, new RenderOptions(6, 4)).Image;
        Assert.Equal(expected.Pixels.ToArray(), ImageReader.Read(output).Pixels.ToArray());
    }

    [Fact]
    public void SceneIsRenderedAtSubpixelsTimesTheSize()
    {
        var output = _scratch.File("s.png");
        Assert.Equal(0, Run("supersample", "--scene", Scene, "--size", "5x3", "--subpixels", "3", "-m", "mc", "-o", output).Code);
        Assert.Equal((5, 3), (ImageReader.Read(output).Width, ImageReader.Read(output).Height));
        Assert.Equal(0, Run("supersample", "--size", "2", "--subpixels", "2", "-m", "mlae", "-o", _scratch.File("builtin.png")).Code);
        Assert.Equal(2, ImageReader.Read(_scratch.File("builtin.png")).Width);
    }

    [Theory]
    [InlineData("mc")]
    [InlineData("qcoin")]
    [InlineData("mlae")]
    [InlineData("mlae-noise")]
    [InlineData("iqae")]
    [InlineData("fae")]
    [InlineData("bae")]
    [InlineData("qss-bayes")]
    [InlineData("powerlaw")]
    [InlineData("qss")]
    public void SameSeedGivesTheSameBytes(string method)
    {
        var input = WriteImage("in.png", 12, 8, (x, y) => ((byte)(x * 20 + y), (byte)(100 + x * y), (byte)(255 - 9 * y)));
        string[] Args(string output, string seed) => ["supersample", "--image", input, "-m", method, "--subpixels", "4", "--seed", seed, "-o", _scratch.File(output)];
        Assert.Equal(0, Run(Args("a.png", "7")).Code);
        Assert.Equal(0, Run(Args("b.png", "7")).Code);
        Assert.Equal(0, Run(Args("c.png", "8")).Code);
        Assert.Equal(File.ReadAllBytes(_scratch.File("a.png")), File.ReadAllBytes(_scratch.File("b.png")));
        Assert.NotEqual(File.ReadAllBytes(_scratch.File("a.png")), File.ReadAllBytes(_scratch.File("c.png")));
    }

    [Theory]
    [InlineData("qcoin")]
    [InlineData("qss")]
    public void NoiseZeroGivesTheNoiselessBytesAndNoisySeedsRepeat(string method)
    {
        // --noise 0 is the ideal machine: the same draws as no --noise. A noisy analytic run is seeded like any
        // other: the same seed gives the same bytes, and at p = 1e-2 the image differs from the ideal one.
        var input = WriteImage("in.png", 12, 8, (x, y) => ((byte)(x * 20 + y), (byte)(100 + x * y), (byte)(255 - 9 * y)));
        string[] Args(string output, params string[] extra) => ["supersample", "--image", input, "-m", method, "--subpixels", "4", "--seed", "7", "-o", _scratch.File(output), .. extra];
        Assert.Equal(0, Run(Args("plain.png")).Code);
        Assert.Equal(0, Run(Args("zero.png", "--noise", "0")).Code);
        Assert.Equal(0, Run(Args("noisy-a.png", "--noise", "0.01")).Code);
        Assert.Equal(0, Run(Args("noisy-b.png", "--noise", "0.01")).Code);
        var plain = File.ReadAllBytes(_scratch.File("plain.png"));
        Assert.Equal(plain, File.ReadAllBytes(_scratch.File("zero.png")));
        Assert.Equal(File.ReadAllBytes(_scratch.File("noisy-a.png")), File.ReadAllBytes(_scratch.File("noisy-b.png")));
        Assert.NotEqual(plain, File.ReadAllBytes(_scratch.File("noisy-a.png")));
    }

    [Fact]
    public void NoisyRunNamesItsModel()
    {
        var input = WriteImage("in.png", 8, 8, (x, y) => ((byte)(x * 30), (byte)(y * 30), 9));
        var (code, output, _) = ConsoleCapture.RunCapturingOutput("supersample", "--image", input, "-m", "mc", "--subpixels", "4", "--noise", "0.003",
            "-o", _scratch.File("out.png"), "--json", _scratch.File("run.json"));
        Assert.Equal(0, code);
        const string description = "depolarizing Pauli noise p = 0.003 per gate and qubit (p/3 each of X, Y, Z), global depolarizing approximation";
        Assert.Contains($"noise model: {description}", output);
        var noise = System.Text.Json.Nodes.JsonNode.Parse(File.ReadAllText(_scratch.File("run.json")))!["noise"]!;
        Assert.Equal("pauli, depolarizing approximation", (string?)noise["model"]);
        Assert.Equal(0.001, (double)noise["rates"]!["px"]!, 12);
        Assert.StartsWith(description, (string?)noise["description"]);
    }

    [Fact]
    public void QubitLossOnTheAnalyticEngineIsOneUsageLineBeforeAnyWork()
    {
        var input = WriteImage("in.png", 8, 8, (_, _) => (5, 5, 5));
        var (code, error) = Run("supersample", "--image", input, "--subpixels", "4", "--qubit-loss", "0.01", "-o", _scratch.File("out.png"));
        Assert.NotEqual(0, code);
        Assert.Contains("--qubit-loss: the analytic engine does not model qubit loss", error);
        Assert.Single(error.Trim().Split('\n'));
        Assert.Equal(["in.png"], _scratch.FileNames());
    }

    [Fact]
    public void ImageNotAMultipleOfTheSubpixelsIsRefused()
    {
        var input = WriteImage("in.png", 6, 8, (_, _) => (1, 2, 3));
        var (code, error) = Run("supersample", "--image", input, "--subpixels", "4", "-o", _scratch.File("out.png"));
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.Equal($"error: {input}: 6x8 is not a multiple of --subpixels 4 on both sides (4x4 subpixels per output pixel); crop it to 4x8", error.Trim());
        Assert.Equal(["in.png"], _scratch.FileNames());
    }

    [Fact]
    public void DamagedImageIsOneErrorLineNamingTheFile()
    {
        var input = _scratch.File("bad.png");
        File.WriteAllText(input, "not an image");
        var (code, error) = Run("supersample", "--image", input, "-o", _scratch.File("out.png"));
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.Single(error.Trim().Split('\n'));
        Assert.StartsWith($"error: {input}: not an image file this program reads", error);
        Assert.Equal(["bad.png"], _scratch.FileNames());
    }

    [Fact]
    public void MissingImageExitsWithTwo()
    {
        var (code, error) = Run("supersample", "--image", _scratch.File("nowhere.png"), "-o", _scratch.File("out.png"));
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.Contains("nowhere.png: no such file", error);
        Assert.Empty(_scratch.FileNames());
    }

    [Theory]
    [InlineData("--queries does not apply to --method qss", "-m", "qss", "--queries", "100")]
    [InlineData("--counter-bits applies to --method qss only", "-m", "mc", "--counter-bits", "4")]
    [InlineData("--planes applies to --method qss only", "-m", "qcoin", "--planes", "2")]
    [InlineData("--qss-values applies to --method qss only", "-m", "mlae", "--qss-values", "continuous")]
    [InlineData("--planes applies to --qss-values planes only", "-m", "qss", "--qss-values", "continuous", "--planes", "4")]
    [InlineData("--steps applies to --method qcoin only", "-m", "mlae", "--steps", "3")]
    [InlineData("--levels applies to --method mlae and mlae-noise only", "-m", "qcoin", "--levels", "3")]
    [InlineData("--method fae needs at least 3 queries (one flip after one Grover operator), got 2", "-m", "fae", "--queries", "2")]
    [InlineData("--method mlae-noise with --levels 10 needs at least 353 queries, got 240", "-m", "mlae-noise", "--levels", "10")]
    [InlineData("--method qcoin with 6 steps needs at least 133 queries, got 100", "-m", "qcoin", "--steps", "6", "--queries", "100")]
    [InlineData("--method mlae with --levels 10 needs at least 353 queries, got 240", "-m", "mlae", "--levels", "10")]
    [InlineData("--size applies to scenes only", "--size", "4")]
    [InlineData("--subpixels must be at least 1, got 0", "--subpixels", "0")]
    [InlineData("--subpixels must be at most 16, got 17", "--subpixels", "17")]
    [InlineData("--queries must be at least 1, got 0", "-m", "mc", "--queries", "0")]
    [InlineData("--counter-bits must be at most 12, got 13", "--counter-bits", "13")]
    [InlineData("--planes must be at least 1, got 0", "--planes", "0")]
    [InlineData("--engine classical is not available here", "--engine", "classical")]
    [InlineData("--method: 'bogus' is not one of mc, qss, qcoin, mlae, mlae-noise, iqae, fae, bae, qss-bayes, powerlaw", "-m", "bogus")]
    [InlineData("--engine: 'bogus' is not one of", "-e", "bogus")]
    [InlineData("--qss-values: '2' is not one of planes, continuous", "--qss-values", "2")]
    public void ImpossibleCombinationsAreUsageErrors(string message, params string[] options)
    {
        var input = WriteImage("in.png", 4, 4, (_, _) => (9, 9, 9));
        var (code, error) = Run(["supersample", "--image", input, .. options, "-o", _scratch.File("out.png")]);
        Assert.Equal(1, code);
        Assert.Contains(message, error);
        Assert.Single(error.Trim().Split('\n'));
        Assert.Equal(["in.png"], _scratch.FileNames());
    }

    [Fact]
    public void ImageAndSceneTogetherAreAUsageError()
    {
        var (code, error) = Run("supersample", "--image", _scratch.File("a.png"), "--scene", Scene, "-o", _scratch.File("out.png"));
        Assert.Equal(1, code);
        Assert.Contains("--image and --scene: give one input, not both", error);
    }

    [Fact]
    public void OutputOverTheInputIsRefused()
    {
        var input = WriteImage("in.png", 4, 4, (x, y) => ((byte)x, (byte)y, 0));
        var before = File.ReadAllBytes(input);
        Assert.Equal(ExitCodes.BadInput, Run("supersample", "--image", input, "--subpixels", "2", "-o", input).Code);
        Assert.Equal(before, File.ReadAllBytes(input));
        Assert.Equal(["in.png"], _scratch.FileNames());
    }

    [Fact]
    public void ForeignFileAtTheConfidenceMapStopsEveryOutput()
    {
        var input = WriteImage("in.png", 4, 4, (x, y) => ((byte)x, (byte)y, 0));
        File.WriteAllText(_scratch.File("out-confidence.png"), "someone else's");
        var (code, error) = Run("supersample", "--image", input, "--subpixels", "2", "-o", _scratch.File("out.png"));
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.Contains("out-confidence.png: exists and was not written by this program", error);
        Assert.Equal("someone else's", File.ReadAllText(_scratch.File("out-confidence.png")));
        Assert.Equal(["in.png", "out-confidence.png"], _scratch.FileNames());
    }

    [Fact]
    public void FullStateAboveThePixelLimitIsRefusedBeforeAnyWork()
    {
        var input = WriteImage("in.png", 17, 16, (_, _) => (5, 5, 5));
        var (code, error) = Run("supersample", "--image", input, "--subpixels", "1", "-e", "fullstate", "-o", _scratch.File("out.png"));
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.Contains($"at most {SupersampleRunSettings.MaxFullStatePixels} output pixels", error);
        Assert.Contains("this input has 272", error);
        Assert.Equal(["in.png"], _scratch.FileNames());
    }

    [Fact]
    public void SceneRenderAboveTheLargestSideIsRefused()
    {
        var (code, error) = Run("supersample", "--scene", Scene, "--size", "8000", "--subpixels", "2", "-o", _scratch.File("out.png"));
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.Contains("16000x16000 render", error);
        Assert.Empty(_scratch.FileNames());
    }
}
