using System.CommandLine;
using System.CommandLine.Parsing;
using QuantumRayTracing.Views;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `supersample`: estimates every output pixel's mean over s x s subpixels, taken from an image file or from a scene
/// rendered classically at s times the resolution, with Monte Carlo, QSS, QCoin or MLAE; writes the image (and
/// for bit-plane QSS the confidence map) and prints the error against the exact average (<see cref="SupersampleRunView"/>).
/// </summary>
public sealed class SupersampleCommand : Command
{
    private readonly Option<FileInfo?> _image = new("--image")
    {
        Description = "Image to supersample (PNG of any bit depth, JPEG, WebP, BMP or GIF): each output pixel averages s x s of its pixels, so both sides must be multiples of s; alpha is composited over black. Default: none, a scene is rendered (--scene).",
    };

    private readonly Option<FileInfo?> _scene = new("--scene")
    {
        Description = $"Scene file rendered classically at s times --size, each s x s block one output pixel. Default (without --image): the built-in Qornell box with {DefaultScene.QornellPrimitives} primitives.",
    };

    private readonly Option<string?> _size = CommonOptions.ImageSize("Output size for a scene, WIDTHxHEIGHT or one number for a square; the scene is rendered at s times it. Default: the scene's size.");

    private readonly Option<int> _subpixels = new Option<int>("--subpixels")
    {
        Description = "s: each output pixel averages s x s subpixels (4: 16 subpixels, 8: 64).",
        DefaultValueFactory = _ => SupersampleSettings.DefaultSide,
    }.Between(1, 16);

    private readonly Option<SupersampleMethod> _method = new Option<SupersampleMethod>("--method", "-m")
    {
        Description = "mc (Monte Carlo), qss (quantum supersampling), qcoin (QCoin, Algorithm 1), mlae (maximum-likelihood amplitude estimation), "
            + "mlae-noise (MLAE for noisy machines: each level's head probability is that of a depolarized coin, "
            + "F^m sin²((2m+1)θ) + (1 − F^m)/2, and the fidelity F per Grover operator is fitted together with the mean, so levels the noise has flattened count for little instead of biasing the estimate; the second half of the budget goes to the level the fitted noise leaves the most information per query), "
            + "iqae (iterative QAE, rerunning its last round against its bias), fae (faster AE, two stages), bae (Bayesian AE: grid posterior, next power by expected variance reduction), qss-bayes (QSS with one ancilla and Bayesian phase estimation instead of the counter), powerlaw (power-law AE, m_k = floor(k^((1-b)/(2b))), b = 0.3, maximum likelihood); docs/estimation.md compares them.",
        DefaultValueFactory = _ => SupersampleSettings.DefaultMethod,
        HelpName = "mc|qss|qcoin|mlae|mlae-noise|iqae|fae|bae|qss-bayes|powerlaw",
    }.Choices();

    private readonly Option<long?> _queries = new Option<long?>("--queries", "-q")
    {
        Description = $"Queries per pixel and channel, every method but qss (a coin flip 1, a Grover operator 2; iqae, fae, bae and qss-bayes may stop below it). Default: {SupersampleSettings.DefaultQueries}. Not for qss, whose count follows from --counter-bits.",
    }.Between(1, 100_000);

    private readonly Option<int?> _steps = new Option<int?>("--steps")
    {
        Description = "qcoin: shift-and-scale steps k. Default: the measured best k for the budget (4 at 240 queries).",
    }.Between(1, 12);

    private readonly Option<int?> _levels = new Option<int?>("--levels")
    {
        Description = "mlae and mlae-noise: amplified levels K besides m = 0 (m = 1, 2, 3, 5, 8, ... growing by 1.5). Default: the largest with at least 8 flips per level (3 at 240 queries).",
    }.Between(0, 12);

    private readonly Option<int?> _counterBits = CommonOptions.CounterBits("qss: counter qubits t; a run costs 2^(t+1) - 1 queries. Default: ceil(log2 N) for bit planes (4 for 4x4), 7 for continuous values (255 queries).", 12);

    private readonly Option<int?> _planes = new Option<int?>("--planes")
    {
        Description = $"qss with bit planes: each channel quantised to P bits, one QSS run per bit plane. Default: {SupersampleSettings.DefaultPlanes} (exact for 8-bit inputs); 1 for black-and-white images.",
    }.Between(1, 8);

    private readonly Option<QssValues?> _qssValues = new Option<QssValues?>("--qss-values")
    {
        Description = "qss: planes (thesis: each bit plane a binary image counted through the lookup table; writes the confidence map) or continuous (paper 003 sec. 3.3: one run on the values, estimate sin²(πy/2^t)). Default: planes.",
        HelpName = "planes|continuous",
    }.Choices();

    private readonly Option<string?> _output = CommonOptions.ImageOutput("PNG to write. Default: <input>-<method>.png in the current directory; bit-plane QSS also writes <output>-confidence.png. An existing file is replaced only if this program wrote it.");

    private readonly EngineOptions _engine = new(EngineKind.Analytic, EngineKind.Analytic, EngineKind.FullState);

    private readonly JsonOption _json = new();

    public SupersampleCommand() : base("supersample", "Estimate each pixel's mean over s x s subpixels (from an image file or a scene) with Monte Carlo, QSS, QCoin, MLAE, IQAE, FAE, BAE or power-law AE; print the error against the exact average.")
    {
        this.AddOptions(_image, _scene, _size, _subpixels, _method, _queries, _steps, _levels, _counterBits, _planes, _qssValues, _output);
        _engine.AddTo(this);
        _json.AddTo(this);
        _method.Choices();
        _qssValues.Choices();
        this.AddRule(EnsureOneInputAndAMethodThatFits);
        SetAction(Execute);
    }

    // One error at most: the inputs first, then the method's options (SupersampleSettings.Problem).
    private void EnsureOneInputAndAMethodThatFits(CommandResult r)
    {
        var settings = MethodSettings(r);
        if ((SupersampleRunSettings.InputProblem(r.GetValue(_image) is not null, r.GetValue(_scene) is not null, r.GetValue(_size) is not null,
            r.GetValue(_engine.Noise) is not null, r.GetValue(_engine.DeviceNoise) is not null || r.GetValue(_engine.ReadoutError) is not null) ?? settings.Problem()) is { } problem) r.AddError(problem);
    }

    // The options with a default are read through ValueOr (the action reads the same values from the parse).
    private SupersampleSettings MethodSettings(CommandResult r) =>
        new(r.ValueOr(_method, SupersampleSettings.DefaultMethod), r.ValueOr(_subpixels, SupersampleSettings.DefaultSide),
            r.GetValue(_queries), r.GetValue(_steps), r.GetValue(_levels), r.GetValue(_counterBits), r.GetValue(_planes), r.GetValue(_qssValues));

    private int Execute(ParseResult parse)
    {
        var settings = Settings(parse);
        string[] inputs = settings.InputFile is { } input ? [input] : [];
        ImageFiles.EnsureWritable(settings.Files, inputs);
        _json.EnsureWritable(parse, [.. settings.Files, .. inputs]);
        EngineFactory.CheckNoise(settings.Engine.Kind, settings.Engine.NoiseModel);
        using var bridges = _engine.StartBridges(parse);
        var run = SupersampleRunView.RunAndPrint(settings, bridges);
        _json.Write(parse, run.Figures, _engine, run.RanOn, settings.Engine.Device is { } device ? RunNoise.Of(settings.Engine.Kind, device)
            : RunNoise.Of(settings.Engine.Kind, settings.Engine.NoiseModel, SupersamplingNoise.Description(settings.Engine.Kind, settings.Engine.NoiseModel)));
        return ExitCodes.Success;
    }

    /// <summary>The run the options ask for; the bridges are started after the outputs are checked.</summary>
    private SupersampleRunSettings Settings(ParseResult parse)
    {
        var method = MethodSettings(parse.CommandResult);
        var (imageFile, sceneFile) = (parse.GetValue(_image), parse.GetValue(_scene));
        return new SupersampleRunSettings(method, imageFile?.FullName, sceneFile?.FullName, OptionText.ParseSize(parse.GetValue(_size)).Size, _engine.GetSetup(parse),
            parse.GetValue(_engine.Seed), parse.GetValue(_output) ?? $"{DefaultScene.StemOf(imageFile?.Name ?? sceneFile?.Name)}-{OptionRules.ChoiceName(method.Method)}.png");
    }
}
