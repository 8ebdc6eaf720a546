using QuantumRayTracing.Bridge;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Estimates;

/// <summary>`estimate` for one ray: its oracle, a Grover iteration, a QSearch run and the supersampling circuits, estimated on every model.</summary>
public static class RayEstimateRun
{
    /// <summary>The table `estimate` prints and the estimates behind it; a progress bar on an interactive console meanwhile.</summary>
    public static (ReportTable Table, IReadOnlyList<CircuitEstimate> Estimates) Run(RayEstimateSettings settings)
    {
        var (scene, geometry) = (settings.Scene, new SceneGeometry(settings.Scene));
        var (input, label) = settings.Pixel is { } pixel
            ? EstimateRay.Pixel(scene, geometry, settings.Width, settings.Height, pixel.X, pixel.Y, settings.Construction)
            : EstimateRay.WorstCase(scene, geometry, settings.Width, settings.Height, settings.Construction);
        var subject = new EstimateSubject(input, settings.Iterations ?? QSearchSchedule.CeilSqrt(geometry.Count), label, settings.Subpixels, settings.CounterBits);
        IReadOnlyList<CircuitEstimate> estimates;
        using (var pool = new BridgePool(settings.Workers))
            estimates = EstimateProgress.Run(new ResourceEstimator(pool, settings.Models, settings.WithCircuits), EstimatedCircuits.All.Select(c => (c, subject)).ToArray(), "estimating");
        return (EstimateTable.For($"Resource estimates: {scene.Name}, {label}", estimates, settings.Models, EstimateTable.Context(scene, geometry, subject)), estimates);
    }
}
