using System.Diagnostics;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// A frame's cost on fault-tolerant machines beside its classical cost on this machine: the recorded
/// analytic render, the price of each distinct run, the frame's cost, and the classical brute-force
/// render of the same frame (the reference `render` compares with) with its wall time per pass.
/// </summary>
public sealed record FrameEstimate(FrameSettings Settings, FrameRecording Recording, FrameCost Cost, RenderResult Classical)
{
    /// <summary>Resource Estimator jobs the pricing took: two traced circuits per distinct oracle shape, one per distinct set of counts.</summary>
    public int EstimatorJobs { get; init; }

    /// <summary>Classical renders timed at least; the fastest counts.</summary>
    public const int ClassicalRepeats = 3;

    /// <summary>More classical renders are timed, up to <see cref="MaxClassicalRepeats"/>, while all of them took less than this.</summary>
    public static readonly TimeSpan ClassicalTimingBudget = TimeSpan.FromSeconds(2);

    public const int MaxClassicalRepeats = 50;

    /// <summary>Wall time of the recorded render, the classical render (the fastest timed) and the pricing.</summary>
    public (TimeSpan Render, TimeSpan Classical, TimeSpan Pricing) WallTimes { get; init; }

    /// <summary>
    /// Records the frame, prices its runs on <paramref name="pool"/> (<see cref="RunPricing"/>), sums
    /// them, and renders the same frame classically.
    /// </summary>
    public static FrameEstimate Run(FrameSettings settings, BridgePool pool, IRenderProgress? progress = null, Action? onJobDone = null)
    {
        var clock = Stopwatch.StartNew();
        var recording = FrameRecording.Record(settings.Scene, settings.Render, settings.Search, progress);
        var renderTime = clock.Elapsed;

        clock.Restart();
        var budget = FrameCost.BudgetFor(recording, settings.ErrorBudget);
        var (prices, jobs) = RunPricing.Price(recording, settings.Construction, settings.Models, budget, pool, onJobDone);
        var cost = FrameCost.Of(recording, prices, settings.Models, budget, settings.Qpus);
        var pricingTime = clock.Elapsed;

        // The classical render, timed as the fastest of several: at least ClassicalRepeats, and more while they
        // take under ClassicalTimingBudget together (a small frame takes milliseconds, and the first run also
        // pays for compiling the code it runs).
        using var classicalSearch = new ClassicalHitSearch();
        RenderResult? classical = null;
        var classicalTime = TimeSpan.MaxValue;
        var spent = TimeSpan.Zero;
        for (var repeat = 0; repeat < ClassicalRepeats || (spent < ClassicalTimingBudget && repeat < MaxClassicalRepeats); repeat++)
        {
            clock.Restart();
            var result = SceneRenderer.Render(settings.Scene, classicalSearch, RenderDefaults.Reference(settings.Render));
            var elapsed = clock.Elapsed;
            spent += elapsed;
            if (elapsed < classicalTime) (classical, classicalTime) = (result, elapsed);
        }
        return new FrameEstimate(settings, recording, cost, classical!)
        {
            EstimatorJobs = jobs,
            WallTimes = (renderTime, classicalTime, pricingTime),
        };
    }

    /// <summary>The classical render's wall time for a pass of the frame, or for the whole render, shading included ("total").</summary>
    public TimeSpan ClassicalTime(string pass) => pass == Cost.Total.Name
        ? WallTimes.Classical
        : Classical.Passes.Where(p => p.Name == pass).Aggregate(TimeSpan.Zero, (sum, p) => sum + p.Elapsed);
}
