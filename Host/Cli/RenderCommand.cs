using System.CommandLine;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Views;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `render`: renders a scene on the chosen engine, compares it with the classical reference and
/// prints the paper's table 1 metrics per pass (<see cref="RenderRunView"/>).
/// </summary>
public sealed class RenderCommand : Command
{
    private readonly Argument<FileInfo?> _scene = CommonOptions.SceneFile();

    private readonly Option<string?> _output = CommonOptions.ImageOutput("PNG to write. Default: <scene>-<engine>.png in the current directory. An existing file is replaced only if this program wrote it.");

    private readonly Option<string?> _size = CommonOptions.ImageSize("Image size, WIDTHxHEIGHT or one number for a square. Default: the scene's.");

    private readonly Option<bool> _reference = new("--reference")
    {
        Description = "Also write the classical reference (<output>-reference.png) and a difference image (<output>-difference.png: differing pixels red).",
    };

    private readonly Option<int> _referenceSamples = CommonOptions.ReferenceSamples("Area samples and VPLs per point of the converged classical reference the render is also compared with when it samples light (area lights or --vpl); 0 skips it. It costs about this many / --area-samples (or --vpl) times a classical render.", min: 0);

    private readonly Option<string?> _maxMemory = CommonOptions.MaxMemory($"Refuse a render of {RenderForecast.LargePixels:N0} pixels or more whose forecast peak memory exceeds SIZE (512M, 4G). Default: the memory this machine has available.");

    private readonly Option<LightEstimator> _lightEstimator = new Option<LightEstimator>("--light-estimator")
    {
        Description = "How each shading point's area light is read from its fixed set of --area-samples samples (a power of two): mc (Monte Carlo; without --light-queries every sample's shadow ray is traced, as always), or a quantum estimator of the set's mean, qcoin, mlae, iqae or bae (analytic engine).",
        DefaultValueFactory = _ => LightEstimator.Mc,
        HelpName = "mc|qcoin|mlae|iqae|bae",
    }.Choices();

    private readonly Option<int?> _lightQueries = new Option<int?>("--light-queries")
    {
        Description = $"Queries per shading point and area light for --light-estimator (one query: one coherent evaluation of a sample's weight and visibility over all primitives; Monte Carlo: one sample drawn from the set). Default with a quantum estimator: {LightEstimation.DefaultQueries}.",
    }.Between(LightEstimation.MinQueries, LightEstimation.MaxQueries);

    private readonly RenderOptionSet _render = new();

    private readonly EngineOptions _engine = new EngineOptions(EngineKind.Analytic,
        EngineKind.FullState, EngineKind.Gate, EngineKind.Analytic, EngineKind.Classical, EngineKind.Bvh, EngineKind.Randomized).WithImagePartsOnCluster();

    private readonly QSearchOptionSet _qsearch = new();

    private readonly JsonOption _json = new();

    public RenderCommand() : base("render", "Render a scene with quantum (or classical) ray searches; print cost per pass (paper table 1) and the error against the classical image.")
    {
        Arguments.Add(_scene);
        this.AddOptions(_output, _size, _reference, _referenceSamples, _maxMemory);
        _render.AddTo(this);
        Options.Add(_render.Budget);
        this.AddOptions(_lightEstimator, _lightQueries);
        _engine.AddTo(this);
        this.AddOptions(_engine.NoiseOracleOption, _idealPlan);
        _qsearch.AddTo(this);
        _json.AddTo(this);
        SetAction(Execute);
    }

    private readonly Option<bool> _idealPlan = new("--ideal-plan")
    {
        Description = "Under a noise model (analytic engine), plan as if the machine were noiseless: the termination rule, the lattice's confirmations, the budget rounds and the classical settling use each Grover run's ideal success probability. By default they use the noisy one, so the budget holds under noise. The expected wrong pixels printed always take the noisy probabilities.",
    };

    private int Execute(ParseResult parse)
    {
        var sceneFile = parse.GetValue(_scene);
        var settings = Settings(parse, sceneFile);
        settings.EnsureRunnable();
        var inputs = sceneFile is null ? Array.Empty<string>() : [sceneFile.FullName];
        ImageFiles.EnsureWritable(settings.Files, inputs);
        _json.EnsureWritable(parse, [.. settings.Files, .. inputs]);
        using var bridges = _engine.StartBridges(parse);
        var run = RenderRunView.RunAndPrint(settings, bridges);
        _json.Write(parse, run.Figures, _engine, run.RanOn, settings.RunNoise);
        return ExitCodes.Success;
    }

    /// <summary>Light estimation, or null for today's tracing of every sample (mc without --light-queries).</summary>
    private LightEstimation? Light(ParseResult parse) => (parse.GetValue(_lightEstimator), parse.GetValue(_lightQueries)) switch
    {
        (LightEstimator.Mc, null) => null,
        var (estimator, queries) => new LightEstimation(estimator, queries ?? LightEstimation.DefaultQueries),
    };

    /// <summary>The run the options ask for; the bridges are started after the outputs are checked.</summary>
    private RenderRunSettings Settings(ParseResult parse, FileInfo? sceneFile)
    {
        var scene = DefaultScene.Load(sceneFile);
        var kind = parse.GetValue(_engine.Engine);
        var (width, height) = OptionText.SizeOr(parse.GetValue(_size), scene);
        var options = _render.Get(parse, width, height, parse.GetValue(_engine.Seed)) with { Budget = _render.BudgetShare(parse), Light = Light(parse) };
        var engine = _engine.GetSetup(parse, _qsearch.Get(parse), _engine.GetNoiseOracle(parse), parse.GetValue(_idealPlan));
        return new RenderRunSettings(scene, options, engine,
            parse.GetValue(_output) ?? $"{DefaultScene.StemOf(sceneFile?.Name)}-{EngineFactory.Name(kind)}.png", parse.GetValue(_reference), parse.GetValue(_referenceSamples),
            OptionText.ParseBytes(parse.GetValue(_maxMemory)).Bytes);
    }
}
