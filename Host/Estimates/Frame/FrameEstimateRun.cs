using QuantumRayTracing.Reports;
using QuantumRayTracing.Views;
using QuantumRayTracing.Cluster;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// `estimate --frame`'s run: the frame priced on a cluster's bridges (when given a cluster file)
/// or on local ones, the render's progress on the console, and the table naming the machine and where the pricing ran.
/// </summary>
public sealed record FrameEstimateRun(FrameEstimate Frame, ReportTable Table, RunPlace PricedOn)
{
    /// <param name="settings">The frame and its pricing.</param>
    /// <param name="clusterFile">The cluster whose workers run the Resource Estimator jobs; null: <paramref name="workers"/> local bridges.</param>
    /// <param name="workers">Local bridges when there is no cluster.</param>
    public static FrameEstimateRun Run(FrameSettings settings, string? clusterFile, int workers)
    {
        using var pool = ClusterBridges.Start(clusterFile, workers);
        var progress = new ConsoleProgress("analytic");
        var frame = FrameEstimate.Run(settings, pool, progress);
        progress.Finish();
        var versions = pool.Bridges[0].Version();
        var machine = MachineDescription.Describe(versions["qsharp"]?.GetValue<string>(), versions["node"]?.GetValue<string>());
        return new FrameEstimateRun(frame, FrameTable.For(frame, machine, clusterFile is null ? null : pool.Place.Description), pool.Place);
    }
}
