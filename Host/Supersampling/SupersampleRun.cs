using QuantumRayTracing.Estimation;
using System.Diagnostics;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Supersampling;

/// <summary>
/// One `supersample`: the noise model checked against the engine, the input read (an image file) or rendered
/// classically at s times the output size (a scene, by default the built-in Qornell box), the QSS lookup table for bit planes, then every pixel and
/// channel estimated on the engine, the error against the exact average, the images written (all or none), and
/// the figures in one record.
/// </summary>
public static class SupersampleRun
{
    /// <param name="settings">The run.</param>
    /// <param name="progress">The classical render of a scene and the estimates, each reported as a render.</param>
    /// <param name="onPlan">Called with what the run models once it is known, before the estimates start.</param>
    public static SupersampleRunResult Run(SupersampleRunSettings settings, IRunProgress? progress = null, Action<SupersamplePlan>? onPlan = null)
    {
        var (method, engineSetup) = (settings.Method, settings.Engine);
        var (kind, noise) = (engineSetup.Kind, engineSetup.NoiseModel);
        EngineFactory.CheckNoise(kind, noise);
        if (method.Method == SupersampleMethod.QssBayes && (engineSetup.Device is not null || kind == EngineKind.Analytic && !noise.IsNoiseless))
            throw new UserError("--method qss-bayes: its single-ancilla shot runs on the fullstate engine, or on the analytic engine without noise; not under a device model");
        var (input, inputName, renderTime) = settings.ImageFile is { } file
            ? (LoadImage(file, method.Side, kind), Path.GetFileName(file), (TimeSpan?)null)
            : RenderScene(settings.SceneFile, settings.Size, method.Side, kind, progress);

        QssLookupTable? table = null;
        string? tablePath = null;
        var cached = false;
        if (method.UsesLookupTable)
        {
            var cache = new QssTableCache(settings.TableDirectory ?? QssTableCache.DefaultDirectory());
            var (n, t) = (method.Subpixels, method.CounterBitsOrDefault);
            table = cache.GetOrBuild(n, t, "exact", () => QssLookupTable.Exact(n, t));
            (tablePath, cached) = (cache.PathFor(n, t, "exact"), cache.LastWasHit);
        }
        var estimator = method.CreateEstimator(table);
        onPlan?.Invoke(new SupersamplePlan(inputName, input, renderTime, table, tablePath, cached, estimator));

        var clock = Stopwatch.StartNew();
        SupersampleResult result;
        try
        {
            var supersampling = progress?.Start(EngineFactory.Name(kind));
            using var engine = CoinEngines.Create(kind, settings.Seed, engineSetup.Workers, engineSetup.MaxQubits, noise, engineSetup.Pool, engineSetup.Device);
            result = ImageSupersampler.Run(input, estimator, engine, supersampling);
        }
        finally
        {
            progress?.Finish();
        }
        var elapsed = clock.Elapsed;

        var error = SupersampleError.Of(input, result);
        var files = settings.Files;
        var images = new List<(RgbImage, string)> { (result.Image, files[0]) };
        if (result.ConfidenceMap is { } map) images.Add((map, files[1]));
        ImageFiles.Write(images);

        var figures = new SupersampleFigures(inputName, input.Image.Width, input.Image.Height, input.Side, input.Width, input.Height,
            renderTime, table?.Readouts, result.Estimator, result.QueriesPerChannel, result.ChannelsEstimated,
            result.QueriesPerChannel * result.ChannelsEstimated * input.Pixels, error,
            result.Confidence?.Average(), result.Confidence?.Min(), elapsed, images.Select(i => i.Item2).ToArray());
        // After the estimates: a cluster's place counts the chunks it had to send again.
        var ranOn = EngineFactory.Place(kind, engineSetup.Pool, engineSetup.Workers);
        return new SupersampleRunResult(figures, ranOn, input, result);
    }

    private static SubpixelImage LoadImage(string path, int s, EngineKind kind)
    {
        var image = ImageReader.Read(path);
        if (image.Width % s != 0 || image.Height % s != 0)
            throw new UserError($"{path}: {image.Width}x{image.Height} is not a multiple of --subpixels {s} on both sides ({s}x{s} subpixels per output pixel)"
                + (image.Width >= s && image.Height >= s ? $"; crop it to {image.Width / s * s}x{image.Height / s * s}" : ""));
        CheckEngine(kind, (long)(image.Width / s) * (image.Height / s));
        return new SubpixelImage(image, s);
    }

    // The scene (or the built-in Qornell box) rendered classically at s times the output size.
    private static (SubpixelImage Input, string Name, TimeSpan? Time) RenderScene(string? path, (int Width, int Height)? size, int s, EngineKind kind, IRunProgress? progress)
    {
        var scene = DefaultScene.Load(path is null ? null : new FileInfo(path));
        var (width, height) = size ?? (scene.Width, scene.Height);
        if ((long)width * s > SceneLoader.MaxImageSide || (long)height * s > SceneLoader.MaxImageSide)
            throw new UserError($"{width}x{height} pixels at --subpixels {s} is a {width * s}x{height * s} render, above the largest side {SceneLoader.MaxImageSide}; use a smaller --size or --subpixels");
        CheckEngine(kind, (long)width * height);
        var clock = Stopwatch.StartNew();
        RgbImage rendered;
        try
        {
            rendered = Renderer.Render(scene, new EngineSetup(EngineKind.Classical), RenderOptions.PaperPipeline(width * s, height * s), progress?.Start("classical render")).Image;
        }
        finally
        {
            progress?.Finish();
        }
        return (new SubpixelImage(rendered, s), scene.Name, clock.Elapsed);
    }

    private static void CheckEngine(EngineKind kind, long pixels)
    {
        if (kind.RunsQSharp && pixels > SupersampleRunSettings.MaxFullStatePixels)
            throw new UserError($"--engine fullstate simulates every pixel and takes about a second per output pixel: at most {SupersampleRunSettings.MaxFullStatePixels} output pixels (e.g. 16x16), this input has {pixels}; use --engine analytic (the same distributions, seeded) or a smaller input");
    }
}
