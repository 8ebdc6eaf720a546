using System.CommandLine;
using QuantumRayTracing.Estimates;

namespace QuantumRayTracing.Cli;

/// <summary>`estimate` for one ray: options → <see cref="RayEstimateSettings"/> → <see cref="RayEstimateRun.Run"/>, printed as a table.</summary>
internal static class EstimateRayAction
{
    public static int Run(EstimateCommand command, ParseResult parse)
    {
        var (scene, width, height) = command.LoadScene(parse);
        var pixel = parse.GetValue(command.Pixel) is { } text ? OptionText.PixelIn(text, width, height) : ((int, int)?)null;
        var estimator = command.Estimator;
        var (table, estimates) = RayEstimateRun.Run(new RayEstimateSettings(scene, width, height, pixel, parse.GetValue(command.Iterations), parse.GetValue(command.Subpixels),
            parse.GetValue(command.CounterBits)!.Value, estimator.Construction(parse), estimator.QubitModels(parse), !parse.GetValue(estimator.NoCircuit), parse.GetValue(estimator.Workers)));
        table.Write(parse.GetValue(estimator.Format));
        command.Json.Write(parse, EstimateFigures.Of(table, estimates));
        return ExitCodes.Success;
    }
}
