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

    /// <summary>Classical renders timed; the fastest counts.</summary>
    public const int ClassicalRepeats = 3;

    /// <summary>Wall time of the recorded render, the classical render (fastest of <see cref="ClassicalRepeats"/>) and the pricing.</summary>
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

        // The classical render, best of three: the first run also pays for compiling the code it runs.
        using var classicalSearch = new ClassicalHitSearch();
        var (classical, classicalTime) = Enumerable.Range(0, ClassicalRepeats).Select(_ =>
        {
            clock.Restart();
            var result = SceneRenderer.Render(settings.Scene, classicalSearch, RenderDefaults.Reference(settings.Render));
            return (result, clock.Elapsed);
        }).MinBy(r => r.Elapsed);
        return new FrameEstimate(settings, recording, cost, classical)
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
