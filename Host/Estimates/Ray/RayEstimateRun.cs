using QuantumRayTracing.Bridge;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// `estimate` for one ray: its oracle, a Grover iteration, a QSearch run and the supersampling circuits, estimated on every
/// model; with a pool instead, the ray's oracle and Grover iteration each beside a pooled search's query and iteration.
/// </summary>
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
        var context = EstimateTable.Context(scene, geometry, subject);
        IEnumerable<EstimatedCircuit> circuits = EstimatedCircuits.All;
        if (settings.PooledRays is { } rays)
        {
            var (pool, poolLabel) = EstimateRay.Pool(scene, geometry, settings.Width, settings.Height, rays, settings.Construction);
            subject = subject with { Pool = pool };
            context = [.. context, EstimateTable.PoolContext(geometry, pool, poolLabel)];
            circuits = [EstimatedCircuits.Oracle, EstimatedCircuits.PooledQuery, EstimatedCircuits.GroverIteration, EstimatedCircuits.PooledIteration];
        }
        IReadOnlyList<CircuitEstimate> estimates;
        using (var bridges = new BridgePool(settings.Workers))
            estimates = EstimateProgress.Run(new ResourceEstimator(bridges, settings.Models, settings.WithCircuits), circuits.Select(c => (c, subject)).ToArray(), "estimating");
        return (EstimateTable.For($"Resource estimates: {scene.Name}, {label}", estimates, settings.Models, context), estimates);
    }
}
