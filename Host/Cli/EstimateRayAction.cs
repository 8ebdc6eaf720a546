using System.CommandLine;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Cli;

/// <summary>`estimate` for one ray: its oracle, a Grover iteration, a QSearch run and the supersampling circuits, estimated on every model.</summary>
internal static class EstimateRayAction
{
    public static int Run(EstimateCommand command, ParseResult parse)
    {
        command.Json.EnsureWritable(parse, parse.GetValue(command.Scene) is { } sceneFile ? [sceneFile.FullName] : []);
        var scene = DefaultScene.Load(parse.GetValue(command.Scene));
        var geometry = new SceneGeometry(scene);
        var (width, height) = OptionText.SizeOr(parse.GetValue(command.Size), scene);
        var construction = command.Estimator.Construction(parse);
        var (input, label) = OptionText.ParsePixel(parse.GetValue(command.Pixel)) is { Pixel: { } pixel }
            ? pixel.X < width && pixel.Y < height
                ? EstimateRay.Pixel(scene, geometry, width, height, pixel.X, pixel.Y, construction)
                : throw new UserError($"--pixel {pixel.X},{pixel.Y} is outside the {width}x{height} image")
            : EstimateRay.WorstCase(scene, geometry, width, height, construction);
        var iterations = parse.GetValue(command.Iterations) ?? QSearchSchedule.CeilSqrt(geometry.Count);
        var subject = new EstimateSubject(input, iterations, label, parse.GetValue(command.Subpixels), parse.GetValue(command.CounterBits));

        var estimator = command.Estimator.Create(parse, out var pool);
        IReadOnlyList<CircuitEstimate> estimates;
        using (pool)
        {
            var jobs = EstimatedCircuits.All.Select(c => (c, subject)).ToArray();
            estimates = EstimateProgress.Run(estimator, jobs, "estimating");
        }

        var table = EstimateTable.For($"Resource estimates: {scene.Name}, {label}", estimates, estimator.Models, EstimateTable.Context(scene, geometry, subject));
        table.Write(parse.GetValue(command.Estimator.Format));
        command.Json.Write(parse, EstimateFigures.Of(table, estimates));
        return ExitCodes.Success;
    }
}
