using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// Supersampling experiments on images (paper 003 fig. 1; thesis 004 tables 4.1-4.2 and its confidence map): inputs
/// rendered classically from the built-in Qornell box, every estimator run exactly as `supersample --engine analytic
/// --seed S` runs it, so any image here can be regenerated with that command.
/// </summary>
public static class SupersamplingImageBenchmark
{
    /// <summary>One estimator on one input with one seed.</summary>
    public sealed record Run(string Image, int Size, int Side, string Method, long Queries, ulong Seed, SupersampleResult Result, SupersampleError Error);

    /// <summary>Pixels whose confidence lies in [Low, High): how many, their mean error (8-bit levels, averaged over channels) and exact share.</summary>
    public sealed record ConfidenceBin(double Low, double High, int Pixels, double MeanError, double ExactShare);

    /// <summary>The built-in Qornell box (64 primitives) rendered classically at <paramref name="size"/> · <paramref name="side"/> pixels square.</summary>
    public static RgbImage RenderQornell(int size, int side)
    {
        var scene = SceneLoader.Parse(QornellBox.Build(DefaultScene.QornellPrimitives).ToJson(), "built-in qornell");
        return Renderer.Render(scene, new EngineSetup(EngineKind.Classical), RenderOptions.PaperPipeline(size * side, size * side)).Image;
    }

    /// <summary>The thesis's black-and-white input: white where the luminance (Rec. 709 weights) is at least half.</summary>
    public static RgbImage BlackAndWhite(RgbImage image) => RgbImage.FromLinear(image.Width, image.Height, (x, y) =>
    {
        var (r, g, b) = image.GetPixel(x, y);
        var white = 0.2126 * r + 0.7152 * g + 0.0722 * b >= 127.5 ? 1.0 : 0.0;
        return (white, white, white);
    });

    public static Run Estimate(string image, SubpixelImage input, SupersampleSettings settings, ulong seed)
    {
        var table = settings.UsesLookupTable ? QssLookupTable.Exact(settings.Subpixels, settings.CounterBitsOrDefault) : null;
        var estimator = settings.CreateEstimator(table);
        using var engine = CoinEngines.Create(Engines.EngineKind.Analytic, seed, 1);
        var result = ImageSupersampler.Run(input, estimator, engine);
        return new Run(image, input.Width, input.Side, Label(settings), estimator.Queries, seed, result, SupersampleError.Of(input, result));
    }

    /// <summary>A short name for a configuration, as the tables print it.</summary>
    public static string Label(SupersampleSettings s) => s.Method switch
    {
        SupersampleMethod.Mc => "MC",
        SupersampleMethod.QCoin => $"QCoin k={s.Steps ?? QCoinEstimator.DefaultSteps(s.QueriesOrDefault)}",
        SupersampleMethod.Mlae => $"MLAE K={s.Levels ?? MaximumLikelihoodEstimator.DefaultLevels(s.QueriesOrDefault)}",
        _ when s.QssValues == QssValues.Continuous => $"QSS cont. t={s.CounterBitsOrDefault}",
        _ => $"QSS planes t={s.CounterBitsOrDefault} P={s.PlanesOrDefault}",
    };

    /// <summary>Each pixel's absolute error (mean over channels, 8-bit levels) times <paramref name="gain"/>, as grey.</summary>
    public static RgbImage ErrorMap(SupersampleError error, int width, int height, double gain) =>
        RgbImage.FromLinear(width, height, (x, y) =>
        {
            var e = error.PixelLevels[y * width + x] * gain / 255;
            return (e, e, e);
        });

    public static List<ConfidenceBin> ByConfidence(IReadOnlyList<double> confidence, IReadOnlyList<double> errors, IReadOnlyList<double> edges)
    {
        var bins = new List<ConfidenceBin>();
        for (var b = 0; b + 1 < edges.Count; b++)
        {
            var last = b + 2 == edges.Count;
            var members = Enumerable.Range(0, confidence.Count)
                .Where(p => confidence[p] >= edges[b] && (confidence[p] < edges[b + 1] || last && confidence[p] <= edges[b + 1])).ToArray();
            bins.Add(new ConfidenceBin(edges[b], edges[b + 1], members.Length,
                members.Length == 0 ? double.NaN : members.Average(p => errors[p]),
                members.Length == 0 ? double.NaN : members.Count(p => errors[p] == 0) / (double)members.Length));
        }
        return bins;
    }

    /// <summary>The share of all error that falls in the <paramref name="share"/> least confident pixels (ties in confidence share it evenly).</summary>
    public static double ErrorInLeastConfident(IReadOnlyList<double> confidence, IReadOnlyList<double> errors, double share)
    {
        var total = errors.Sum();
        if (total == 0) return double.NaN;
        // A group of equal confidences straddling the cut counts in proportion.
        var cut = share * confidence.Count;
        var inside = 0.0;
        var groups = Enumerable.Range(0, confidence.Count).GroupBy(p => confidence[p]).OrderBy(g => g.Key);
        var seen = 0;
        foreach (var group in groups)
        {
            var count = group.Count();
            var part = Math.Clamp((cut - seen) / count, 0, 1);
            inside += part * group.Sum(p => errors[p]);
            seen += count;
            if (seen >= cut) break;
        }
        return inside / total;
    }
}
