using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Output;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `supersample`: estimates every output pixel's mean over s x s subpixels, taken from an image file or from a scene
/// rendered classically at s times the resolution, with Monte Carlo, QSS, QCoin or MLAE; writes the image (and
/// for bit-plane QSS the confidence map) and prints the error against the exact average.
/// </summary>
public sealed class SupersampleCommand : Command
{
    /// <summary>The fullstate engine simulates every (pixel, channel) item: above this many output pixels it is refused.</summary>
    public const int MaxFullStatePixels = 256;

    public const SupersampleMethod DefaultMethod = SupersampleMethod.Qss;

    public const int DefaultSubpixels = 4;

    private readonly Option<FileInfo?> _image = new("--image")
    {
        Description = "Image to supersample (PNG of any bit depth, JPEG, WebP, BMP or GIF): each output pixel averages s x s of its pixels, so both sides must be multiples of s; alpha is composited over black. Default: none, a scene is rendered (--scene).",
    };

    private readonly Option<FileInfo?> _scene = new("--scene")
    {
        Description = $"Scene file rendered classically at s times --size, each s x s block one output pixel. Default (without --image): the built-in Qornell box with {RenderCommand.DefaultQornellPrimitives} primitives.",
    };

    private readonly Option<string?> _size = new("--size")
    {
        Description = "Output size for a scene, WIDTHxHEIGHT or one number for a square; the scene is rendered at s times it. Default: the scene's size.",
        HelpName = "WxH",
    };

    private readonly Option<int> _subpixels = new("--subpixels")
    {
        Description = "s: each output pixel averages s x s subpixels (4: 16 subpixels, 8: 64).",
        DefaultValueFactory = _ => DefaultSubpixels,
    };

    private readonly Option<SupersampleMethod> _method = new("--method", "-m")
    {
        Description = "mc (Monte Carlo), qss (quantum supersampling), qcoin (QCoin, Algorithm 1), mlae (maximum-likelihood amplitude estimation), "
            + "mlae-noise (MLAE for noisy machines: each level's head probability is that of a depolarized coin, "
            + "F^m sin²((2m+1)θ) + (1 − F^m)/2, and the fidelity F per Grover operator is fitted together with the mean, so levels the noise has flattened count for little instead of biasing the estimate; the second half of the budget goes to the level the fitted noise leaves the most information per query).",
        DefaultValueFactory = _ => DefaultMethod,
        HelpName = "mc|qss|qcoin|mlae|mlae-noise",
    };

    private readonly Option<long?> _queries = new("--queries", "-q")
    {
        Description = $"Queries per pixel and channel for mc, qcoin, mlae and mlae-noise (a coin flip 1, a Grover operator 2). Default: {SupersampleSettings.DefaultQueries}. Not for qss, whose count follows from --counter-bits.",
    };

    private readonly Option<int?> _steps = new("--steps")
    {
        Description = "qcoin: shift-and-scale steps k. Default: the measured best k for the budget (4 at 240 queries).",
    };

    private readonly Option<int?> _levels = new("--levels")
    {
        Description = "mlae and mlae-noise: amplified levels K besides m = 0 (m = 1, 2, 3, 5, 8, ... growing by 1.5). Default: the largest with at least 8 flips per level (3 at 240 queries).",
    };

    private readonly Option<int?> _counterBits = new("--counter-bits", "-t")
    {
        Description = "qss: counter qubits t; a run costs 2^(t+1) - 1 queries. Default: ceil(log2 N) for bit planes (4 for 4x4), 7 for continuous values (255 queries).",
    };

    private readonly Option<int?> _planes = new("--planes")
    {
        Description = $"qss with bit planes: each channel quantised to P bits, one QSS run per bit plane. Default: {SupersampleSettings.DefaultPlanes} (exact for 8-bit inputs); 1 for black-and-white images.",
    };

    private readonly Option<QssValues?> _qssValues = new("--qss-values")
    {
        Description = "qss: planes (thesis: each bit plane a binary image counted through the lookup table; writes the confidence map) or continuous (paper 003 sec. 3.3: one run on the values, estimate sin²(πy/2^t)). Default: planes.",
        HelpName = "planes|continuous",
    };

    private readonly Option<string?> _output = new("--output", "-o")
    {
        Description = "PNG to write. Default: <input>-<method>.png in the current directory; bit-plane QSS also writes <output>-confidence.png. An existing file is replaced only if this program wrote it.",
    };

    private readonly EngineOptions _engine = new(EngineKind.Analytic, EngineKind.Analytic, EngineKind.FullState);

    private readonly JsonOption _json = new();

    public SupersampleCommand() : base("supersample", "Estimate each pixel's mean over s x s subpixels (from an image file or a scene) with Monte Carlo, QSS, QCoin or MLAE; print the error against the exact average.")
    {
        Options.Add(_image);
        Options.Add(_scene);
        Options.Add(_size);
        Options.Add(_subpixels);
        Options.Add(_method);
        Options.Add(_queries);
        Options.Add(_steps);
        Options.Add(_levels);
        Options.Add(_counterBits);
        Options.Add(_planes);
        Options.Add(_qssValues);
        Options.Add(_output);
        _engine.AddTo(this);
        _json.AddTo(this);
        _method.Choices();
        _qssValues.Choices();
        _subpixels.Between(1, 16);
        _queries.Between(1, 100_000);
        _steps.Between(1, 12);
        _levels.Between(0, 12);
        _counterBits.Between(1, 12);
        _planes.Between(1, 8);
        _size.Validators.Add(r =>
        {
            if (RenderCommand.ParseSize(r.GetValueOrDefault<string?>()) is { Error: { } error }) r.AddError($"--size: {error}");
        });
        Validators.Add(r =>
        {
            SupersampleSettings settings;
            try
            {
                settings = Settings(r);
            }
            catch (InvalidOperationException)
            {
                // A value that does not parse (say --method bogus) has its own error; combinations need parsed values.
                return;
            }
            if (r.GetValue(_image) is not null && r.GetValue(_scene) is not null) r.AddError("--image and --scene: give one input, not both");
            else if (r.GetValue(_image) is not null && r.GetValue(_size) is not null) r.AddError("--size applies to scenes only: an image's output size is its size divided by --subpixels");
            else if (settings.Problem() is { } problem) r.AddError(problem);
        });
        SetAction(Execute);
    }

    // Inside a command validator, an option left out reads as default(T), not its default value: those are filled in here.
    private SupersampleSettings Settings(System.CommandLine.Parsing.CommandResult r) =>
        new(r.GetResult(_method) is null ? DefaultMethod : r.GetValue(_method), r.GetResult(_subpixels) is null ? DefaultSubpixels : r.GetValue(_subpixels),
            r.GetValue(_queries), r.GetValue(_steps), r.GetValue(_levels), r.GetValue(_counterBits), r.GetValue(_planes), r.GetValue(_qssValues));

    private int Execute(ParseResult parse)
    {
        var settings = new SupersampleSettings(parse.GetValue(_method), parse.GetValue(_subpixels), parse.GetValue(_queries), parse.GetValue(_steps),
            parse.GetValue(_levels), parse.GetValue(_counterBits), parse.GetValue(_planes), parse.GetValue(_qssValues));
        var imageFile = parse.GetValue(_image);
        var sceneFile = parse.GetValue(_scene);
        var inputPath = imageFile?.FullName ?? sceneFile?.FullName;
        var stem = imageFile is not null ? Path.GetFileNameWithoutExtension(imageFile.Name)
            : sceneFile is not null ? Path.GetFileNameWithoutExtension(sceneFile.Name)
            : $"qornell-{RenderCommand.DefaultQornellPrimitives}";
        var methodName = OptionRules.ChoiceName(settings.Method);
        var output = parse.GetValue(_output) ?? $"{stem}-{methodName}.png";
        var outputs = settings.UsesLookupTable ? new[] { output, RenderCommand.Sibling(output, "confidence") } : [output];
        ImageFiles.EnsureWritable(outputs, inputPath is null ? [] : [inputPath]);
        _json.EnsureWritable(parse, inputPath is null ? outputs : [.. outputs, inputPath]);

        var kind = parse.GetValue(_engine.Engine);
        var noise = _engine.GetNoise(parse);
        EngineOptions.CheckNoise(kind, noise);
        using var bridges = _engine.StartBridges(parse);
        var (input, inputName, inputTime) = imageFile is not null
            ? (LoadImage(imageFile, settings.Side, kind), imageFile.Name, (TimeSpan?)null)
            : RenderScene(sceneFile, RenderCommand.ParseSize(parse.GetValue(_size)).Size, settings.Side, kind);

        QssLookupTable? table = null;
        if (settings.UsesLookupTable)
        {
            var cache = new QssTableCache(QssTableCache.DefaultDirectory());
            var (n, t) = (settings.Subpixels, settings.CounterBitsOrDefault);
            table = cache.GetOrBuild(n, t, "exact", () => QssLookupTable.Exact(n, t));
            Console.WriteLine($"QSS lookup table: {table.Readouts} readouts x {n + 1} hit counts, exact, {(cache.LastWasHit ? "read from" : "written to")} {cache.PathFor(n, t, "exact")}");
        }
        var estimator = settings.CreateEstimator(table);
        Console.WriteLine($"{estimator.Name}: {estimator.Queries} queries per pixel per channel ({Registers(settings)})");

        var clock = Stopwatch.StartNew();
        SupersampleResult result;
        var supersampling = new ConsoleProgress(EngineOptions.Name(kind));
        Console.WriteLine($"noise model: {EngineOptions.NoiseDescription(kind, noise)}");
        using (var engine = CreateEngine(kind, parse.GetValue(_engine.Seed), parse.GetValue(_engine.Workers), parse.GetValue(_engine.MaxQubits), noise, bridges))
            result = ImageSupersampler.Run(input, estimator, engine, supersampling);
        supersampling.Finish();
        var elapsed = clock.Elapsed;

        var error = SupersampleError.Of(input, result);
        var images = new List<(RgbImage, string)> { (result.Image, output) };
        if (result.ConfidenceMap is { } map) images.Add((map, outputs[1]));
        ImageFiles.Write(images);

        var figures = new SupersampleFigures(inputName, input.Image.Width, input.Image.Height, input.Side, input.Width, input.Height,
            inputTime, table?.Readouts, result.Estimator, result.QueriesPerChannel, result.ChannelsEstimated,
            result.QueriesPerChannel * result.ChannelsEstimated * input.Pixels, error,
            result.Confidence?.Average(), result.Confidence?.Min(), elapsed, images.Select(i => i.Item2).ToArray());
        var ranOn = EngineOptions.Place(kind, bridges, parse.GetValue(_engine.Workers));
        Print(figures, EngineOptions.Name(kind), EngineOptions.NoiseDescription(kind, noise), noise.IsNoiseless, ranOn.Description);
        _json.Write(parse, figures, _engine, ranOn);
        return 0;
    }

    private static void Print(SupersampleFigures figures, string engineName, string noise, bool noiseless, string where)
    {
        var error = figures.Error;
        var channels = figures.ChannelsEstimated == 1 ? "one channel (grey input), copied to R, G and B" : "R, G and B each";
        Console.WriteLine($"queries: {figures.QueriesPerChannel} per pixel per channel, {channels}; {figures.TotalQueries:N0} in all");
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"error against the exact average: mean absolute {error.MeanLevels:0.000} levels of 255 ({error.MeanFraction:0.00000}; {error.EstimatorError:0.00000} before 8-bit rounding), zero-error pixels {error.ExactPixels} of {error.Pixels} ({error.ExactShare:P1})"));
        if (figures is { MeanConfidence: { } mean, LowestConfidence: { } lowest })
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"confidence: mean {mean:0.000}, lowest {lowest:0.000} (1 = every bit plane read with certainty)"));
        Console.WriteLine($"wall time: {figures.WallTime.TotalSeconds:0.00} s on the {engineName} engine{(noiseless ? "" : $" under {noise}")}; ran on {where}");
        foreach (var path in figures.Written) Console.WriteLine($"wrote {path}");
    }

    private static SubpixelImage LoadImage(FileInfo file, int s, EngineKind kind)
    {
        var image = ImageReader.Read(file.FullName);
        if (image.Width % s != 0 || image.Height % s != 0)
            throw new UserError($"{file.FullName}: {image.Width}x{image.Height} is not a multiple of --subpixels {s} on both sides ({s}x{s} subpixels per output pixel)"
                + (image.Width >= s && image.Height >= s ? $"; crop it to {image.Width / s * s}x{image.Height / s * s}" : ""));
        CheckEngine(kind, (long)(image.Width / s) * (image.Height / s));
        var input = new SubpixelImage(image, s);
        Console.WriteLine($"{file.Name}: {image.Width}x{image.Height}{(input.IsGrey ? ", grey" : "")}, {s}x{s} = {input.Count} subpixels per output pixel: {input.Width}x{input.Height} output");
        return input;
    }

    // The scene (or the built-in Qornell box) rendered classically at s times the output size.
    private static (SubpixelImage Input, string Name, TimeSpan? Time) RenderScene(FileInfo? file, (int Width, int Height)? size, int s, EngineKind kind)
    {
        var scene = file is null
            ? SceneLoader.Parse(QornellBox.Build(RenderCommand.DefaultQornellPrimitives).ToJson(), $"built-in qornell-{RenderCommand.DefaultQornellPrimitives}")
            : SceneLoader.Load(file.FullName);
        var (width, height) = size ?? (scene.Width, scene.Height);
        if ((long)width * s > SceneLoader.MaxImageSide || (long)height * s > SceneLoader.MaxImageSide)
            throw new UserError($"{width}x{height} pixels at --subpixels {s} is a {width * s}x{height * s} render, above the largest side {SceneLoader.MaxImageSide}; use a smaller --size or --subpixels");
        CheckEngine(kind, (long)width * height);
        var clock = Stopwatch.StartNew();
        var progress = new ConsoleProgress("classical render");
        using var classical = new ClassicalHitSearch();
        var rendered = SceneRenderer.Render(scene, classical, new RenderOptions(width * s, height * s), progress).Image;
        progress.Finish();
        var time = clock.Elapsed;
        Console.WriteLine($"{scene.Name}: rendered classically at {width * s}x{height * s} in {time.TotalSeconds:0.00} s, {s}x{s} = {s * s} subpixels per output pixel: {width}x{height} output");
        return (new SubpixelImage(rendered, s), scene.Name, time);
    }

    private static void CheckEngine(EngineKind kind, long pixels)
    {
        if (kind == EngineKind.FullState && pixels > MaxFullStatePixels)
            throw new UserError($"--engine fullstate simulates every pixel and takes about a second per output pixel: at most {MaxFullStatePixels} output pixels (e.g. 16x16), this input has {pixels}; use --engine analytic (the same distributions, seeded) or a smaller input");
    }

    /// <remarks>The fullstate engine runs on <paramref name="pool"/> when given, without stopping it, else on bridges of its own.</remarks>
    public static ISupersamplingEngine CreateEngine(EngineKind kind, ulong seed, int workers, int? maxQubits = null, Noise.NoiseModel? noise = null, Bridge.BridgePool? pool = null) => kind switch
    {
        EngineKind.FullState => new FullStateSupersamplingEngine(pool ?? new Bridge.BridgePool(workers), ownsPool: pool is null, maxQubits: maxQubits, noise: noise),
        _ => new AnalyticSupersamplingEngine(new SeededRandom(seed).Fork(RandomStreams.Engine), noise),
    };

    // What one estimate holds on a quantum computer: ceil(log2 N) subpixel qubits, a coin, and QSS's counter.
    private static string Registers(SupersampleSettings settings)
    {
        var index = CoinRegisters.SubpixelQubits(settings.Subpixels);
        var counter = settings.Method == SupersampleMethod.Qss ? $" + {settings.CounterBitsOrDefault} counter" : "";
        return settings.Method == SupersampleMethod.Mc
            ? "each query samples one random subpixel"
            : $"registers: {index} subpixel + 1 coin{counter} qubits";
    }
}
