using System.Diagnostics;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;
using static System.FormattableString;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// What a large render will take, said before it starts: peak memory and wall time, from a calibration run of the same
/// scene, engine and options at <see cref="CalibrationSide"/>² and half that (the render and its classical references), after
/// a smaller warm-up run; the time is a line through the two, in the pixel count.
/// </summary>
/// <remarks>
/// Large renders are tiled (<see cref="TiledRender"/>): the renderer holds the work of the tiles it renders at once
/// (<see cref="LocalParts.TilesAtOnce"/>), each tile's surface points
/// and, while a pass runs, that pass's state per ray (camera and shadow rays themselves are computed when read), about
/// <see cref="BytesPerRay"/> per ray over the largest traced tile; and per pixel of the image, <see cref="BytesPerPixel"/>
/// (the render's and the reference's 8-bit images and the image encoder's buffer). Above <see cref="BaseBytes"/>, rounded up
/// from the peak resident memory `bench scale` measured (docs/scale.md, docs/rendering.md). The calibration gives the rays
/// per pixel. Larger renders spend less time per pixel than the calibration's, so the time is an upper estimate (docs/scale.md
/// sets each forecast beside the measured times).
/// </remarks>
public sealed record RenderForecast(long Pixels, double RaysPerPixel, long PeakBytes, TimeSpan Time)
{
    /// <summary>A cluster's workers render the image (`render --cluster`): the time is this machine's alone, the memory an upper bound (the tiles' work is the workers').</summary>
    public bool ImageOnCluster { get; init; }

    /// <summary>Renders from this many pixels (1024x1024) on are forecast first.</summary>
    public const long LargePixels = 1L << 20;

    public const int CalibrationSide = 128;

    // Two tiles at once: scale.md's classical 2048x2048 peaked at 539 MB against a forecast of 532 MB from 320 MB.
    public const long BaseBytes = 352L << 20;

    public const long BytesPerRay = 96;

    public const long BytesPerPixel = 8;

    /// <summary>Whether <paramref name="settings"/> ask for a render large enough to forecast: on an engine whose work runs here in C#.</summary>
    public static bool Applies(RenderRunSettings settings) =>
        (long)settings.Options.Width * settings.Options.Height >= LargePixels && !settings.Engine.Kind.RunsQSharp;

    public static RenderForecast Of(RenderRunSettings settings)
    {
        var options = settings.Options;
        RenderOptions At(int side)
        {
            var (width, height) = (Math.Min(options.Width, side), Math.Min(options.Height, side));
            return options with { Width = width, Height = height, LatticeLevels = Math.Min(options.LatticeLevels, RenderDefaults.LatticeLevelsFor(width, height)) };
        }
        // A warm-up run first (it pays for compiling the renderer), then two timed sizes: a render's time is a fixed
        // part (planning, the first lattice levels) plus a part per pixel, fitted through the two.
        Calibrate(settings, At(CalibrationSide / 4));
        var (small, large) = (At(CalibrationSide / 2), At(CalibrationSide));
        var (smallTime, _) = Timed(settings, small);
        var (largeTime, rays) = Timed(settings, large);
        var (smallPixels, largePixels) = ((double)small.Width * small.Height, (double)large.Width * large.Height);
        var perPixel = Math.Max(0, (largeTime - smallTime).TotalSeconds / Math.Max(1, largePixels - smallPixels));
        var pixels = (long)options.Width * options.Height;
        var time = largeTime + TimeSpan.FromSeconds(perPixel * (pixels - largePixels));
        var raysPerPixel = rays / largePixels;
        // The tiles rendered at once here each hold their work; a cluster's workers hold theirs.
        var tiles = settings.Engine.ImagePartsOnCluster ? 1 : LocalParts.TilesAtOnce(settings.Engine.Kind);
        var tileBytes = (long)(BytesPerRay * raysPerPixel * TiledRender.MostTracedPixels(options.LatticeLevels));
        return new RenderForecast(pixels, raysPerPixel, BaseBytes + tiles * tileBytes + BytesPerPixel * pixels, time)
        {
            ImageOnCluster = settings.Engine.ImagePartsOnCluster,
        };
    }

    private static (TimeSpan Time, long Rays) Timed(RenderRunSettings settings, RenderOptions options)
    {
        var clock = Stopwatch.StartNew();
        var rays = Calibrate(settings, options);
        return (clock.Elapsed, rays);
    }

    // The render and its classical references at the calibration size; the render's rays.
    private static long Calibrate(RenderRunSettings settings, RenderOptions small)
    {
        // Timed here even when a cluster's workers will render the image: a small render there times the trip, not the work.
        var rays = Renderer.Render(settings.Scene, settings.Engine with { ImagePartsOnCluster = false }, small).Total.Rays;
        var classical = new EngineSetup(EngineKind.Classical);
        Renderer.Render(settings.Scene, classical, RenderDefaults.Reference(small));
        if (settings.WithConverged) Renderer.Render(settings.Scene, classical, RenderDefaults.Converged(small, Math.Max(1, settings.ReferenceSamples)));
        return rays;
    }

    /// <summary>Refuses, naming the option, a render whose forecast peak exceeds <paramref name="limitBytes"/>.</summary>
    public void EnsureFits(long limitBytes, bool limitGiven)
    {
        if (PeakBytes <= limitBytes) return;
        var limit = limitGiven ? $"the --max-memory limit of {Bytes(limitBytes)}" : $"the {Bytes(limitBytes)} this machine has available (--max-memory sets the limit)";
        throw new UserError(Invariant($"--size: a render of {Pixels:N0} pixels needs about {Bytes(PeakBytes)} (forecast: {BytesPerPixel} bytes per pixel and a tile's {RaysPerPixel:F2} rays per pixel x {BytesPerRay} bytes), more than {limit}; render a smaller size"));
    }

    /// <summary>A byte count as people read it: 512 MB, 3.2 GB.</summary>
    public static string Bytes(long bytes) =>
        bytes >= 1L << 30 ? Invariant($"{bytes / (double)(1L << 30):F1} GB") : Invariant($"{bytes / (double)(1L << 20):F0} MB");
}
