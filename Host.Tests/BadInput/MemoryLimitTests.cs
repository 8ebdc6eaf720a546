using QuantumRayTracing.Cli;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.BadInput;

/// <summary>
/// `render --max-memory`: a large render is forecast before it starts and refused, with one line and no file, when the
/// forecast exceeds the limit; the limit's own syntax is checked while parsing.
/// </summary>
[Collection(BadInputCollection.Name)]
public sealed class MemoryLimitTests : IDisposable
{
    private static readonly string Scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");

    private readonly ScratchDirectory _output = new("qrt-memory-limit-");

    public void Dispose() => _output.Dispose();

    [Fact]
    public void ARenderForecastPastTheLimitIsRefusedBeforeItStarts()
    {
        // 1024x1024 is the smallest forecast size; about 3 rays per pixel at 512 bytes each is over a gigabyte, far above 64 MB.
        var outcome = Outcome.Of("render", Scene, "-e", "classical", "--size", "1024", "--max-memory", "64M", "-o", _output.File("big.png"));
        outcome.AssertBadInput("--size", "more than the --max-memory limit of 64 MB");
        Outcome.AssertEmpty(_output.Path);
    }

    /// <summary>The forecast is handed out before the refusal, its rays per pixel those of the same render at 128x128.</summary>
    [Fact]
    public void TheForecastComesFirstWithTheCalibrationsRaysPerPixel()
    {
        var scene = Intersection.TestScenes.Load("qornell-8.json");
        var settings = new RenderRunSettings(scene, RenderDefaults.Options(1024, 1024), new EngineSetup(EngineKind.Analytic), _output.File("big.png"), MaxMemory: 1L << 20);
        RenderForecast? told = null;
        var refused = Assert.Throws<QuantumRayTracing.Output.UserError>(() => RenderRun.Run(settings, null, f => told = f));
        Assert.Contains("--max-memory limit of 1 MB", refused.Message);
        var calibration = Renderer.Render(scene, settings.Engine, RenderDefaults.Options(128, 128)).Total.Rays;
        Assert.NotNull(told);
        Assert.Equal(calibration / (128.0 * 128), told.RaysPerPixel, 9);
        Assert.Equal(1024L * 1024, told.Pixels);
        Assert.True(told.PeakBytes > RenderForecast.BaseBytes + 1024L * 1024 * RenderForecast.BytesPerPixel + TiledRender.MostTracedPixels(settings.Options.LatticeLevels) * RenderForecast.BytesPerRay,
            "the image's bytes and at least one ray per pixel of a tile");
        Outcome.AssertEmpty(_output.Path);
    }

    [Theory]
    [InlineData("12X")]
    [InlineData("-1G")]
    [InlineData("G")]
    public void ALimitThatIsNoSizeIsAUsageError(string limit) =>
        Outcome.Of("render", Scene, "-e", "classical", "--size", "4", "--max-memory", limit, "-o", _output.File("x.png"))
            .AssertUsageError("--max-memory", $"expected a size such as 512M or 4G, got '{limit}'", _output.Path);

    [Theory]
    [InlineData("512M", 512L << 20)]
    [InlineData("4G", 4L << 30)]
    [InlineData("1.5g", 3L << 29)]
    [InlineData("2048", 2048L)]
    [InlineData("64k", 64L << 10)]
    public void SizesReadAsPeopleWriteThem(string text, long bytes) => Assert.Equal(bytes, OptionText.ParseBytes(text).Bytes);

    [Fact]
    public void SmallRendersAndTheQSharpEnginesAreNotForecast()
    {
        var scene = Intersection.TestScenes.Load("qornell-8.json");
        RenderRunSettings At(int side, EngineKind engine) => new(scene, RenderOptions.PaperPipeline(side, side), new EngineSetup(engine), "x.png");
        Assert.False(RenderForecast.Applies(At(1023, EngineKind.Classical)));
        Assert.True(RenderForecast.Applies(At(1024, EngineKind.Classical)));
        Assert.False(RenderForecast.Applies(At(1024, EngineKind.FullState)));
    }
}
