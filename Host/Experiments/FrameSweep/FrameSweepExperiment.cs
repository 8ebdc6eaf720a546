using QuantumRayTracing.Bridge;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `estimate frame-sweep`: whole-frame costs on fault-tolerant machines for Qornell-64 and Depth Complexity 64 at several
/// sizes and for the Qornell box against N, with a plot of runtime per frame against N (docs/frame-sweep.md);
/// <see cref="HardwareReport"/> composes the report.
/// </summary>
public static class FrameSweepExperiment
{
    /// <summary>The report's plot, by name, for checking its file before the work.</summary>
    public static readonly string[] Pictures = [HardwareReport.RuntimePlot];

    public static Report Run(FrameSweepSettings settings, Action<string> progress)
    {
        var qornell64 = Qornell(64);
        var depthComplexity = SceneLoader.Parse(DepthComplexityScene.Build(64).ToJson(), "built-in depth-complexity-64");
        using var pool = new BridgePool(settings.Workers);
        // A frame is priced once, however many tables show it.
        var frames = new Dictionary<(string, int), FrameEstimate>();
        FrameEstimate Frame(string key, Scene scene, int size)
        {
            if (frames.TryGetValue((key, size), out var frame)) return frame;
            progress($"{scene.Name}, {size}x{size}: rendering and pricing");
            var frameSettings = new FrameSettings(scene, RenderDefaults.Options(size, size, settings.Seed) with { Budget = null }, new QSearchOptions(), settings.Construction, settings.Models, settings.ErrorBudget, settings.Qpus);
            frame = frames[(key, size)] = FrameEstimate.Run(frameSettings, pool, new TenthsProgress($"{scene.Name}, {size}x{size}", progress));
            progress($"{scene.Name}, {size}x{size}: {frame.Recording.Runs.Count} runs, {frame.EstimatorJobs} estimator jobs, render {frame.WallTimes.Render.TotalSeconds:0.0} s, pricing {frame.WallTimes.Pricing.TotalSeconds:0.0} s");
            return frame;
        }

        var scenes = settings.Sizes.Select(s => ("Qornell-64", s, Frame("qornell-64", qornell64, s)))
            .Concat(settings.Sizes.Select(s => ("Depth Complexity 64", s, Frame("depth-complexity-64", depthComplexity, s)))).ToArray();
        var byPrimitives = settings.Primitives.Order()
            .Select(n => (n, Frame($"qornell-{n}", n == 64 ? qornell64 : Qornell(n), settings.ScalingSize))).ToArray();
        var detailed = Frame("qornell-64", qornell64, settings.DetailedSize);
        var paper = EstimateSweep.Subject(4, EstimateSweep.DefaultCoordinateBits) with { Iterations = 1 };
        var device = new ResourceEstimator(pool, settings.Models, withCircuits: false)
            .Estimate([(EstimatedCircuits.SearchRun, paper with { Oracle = paper.Oracle with { Construction = settings.Construction } })])[0];
        return new HardwareReport(scenes, byPrimitives, settings.ScalingSize, detailed, device).ToReport(settings.Machine);
    }

    /// <summary>A line per tenth of each pass, so a long frame shows it is moving and a log stays short.</summary>
    private sealed class TenthsProgress(string label, Action<string> lines) : IRenderProgress
    {
        private string _last = "";

        public void Report(string stage, double done)
        {
            var line = $"{label}: {stage} {(int)Math.Floor(Math.Clamp(done, 0, 1) * 10) * 10}%";
            if (line == _last) return;
            _last = line;
            lines(line);
        }
    }

    private static Scene Qornell(int primitives) => SceneLoader.Parse(QornellBox.Build(primitives).ToJson(), $"built-in qornell-{primitives}");
}
