using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;

using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Views;

/// <summary>`supersample` on the console: what a run models before the estimates start, and its figures after.</summary>
public static class SupersampleRunView
{
    /// <summary>What the run models, printed before the estimates start.</summary>
    public static void PrintPlan(SupersampleRunSettings settings, SupersamplePlan plan)
    {
        var (input, s) = (plan.Input, plan.Input.Side);
        Console.WriteLine(plan.RenderTime is { } time
            ? $"{plan.InputName}: rendered classically at {input.Image.Width}x{input.Image.Height} in {time.TotalSeconds:0.00} s, {s}x{s} = {input.Count} subpixels per output pixel: {input.Width}x{input.Height} output"
            : $"{plan.InputName}: {input.Image.Width}x{input.Image.Height}{(input.IsGrey ? ", grey" : "")}, {s}x{s} = {input.Count} subpixels per output pixel: {input.Width}x{input.Height} output");
        if (plan.Table is { } table)
            Console.WriteLine($"QSS lookup table: {table.Readouts} readouts x {table.Subpixels + 1} hit counts, exact, {(plan.TableWasCached ? "read from" : "written to")} {plan.TablePath}");
        Console.WriteLine($"{plan.Estimator.Name}: {AtMost(settings)}{plan.Estimator.Queries} queries per pixel per channel ({Registers(settings.Method, settings.Engine.Device is not null)})");
        Console.WriteLine($"noise model: {NoiseDescription(settings)}");
    }

    private static string AtMost(SupersampleRunSettings settings) => settings.Method.MayStopBelowBudget ? "at most " : "";

    /// <summary>The run on <paramref name="pool"/> (null: local bridges): its plan first, its progress on standard error, its figures after.</summary>
    public static SupersampleRunResult RunAndPrint(SupersampleRunSettings settings, Bridge.BridgePool? pool)
    {
        var run = SupersampleRun.Run(settings with { Engine = settings.Engine.OnBridges(pool) }, new ConsoleRunProgress(), plan => PrintPlan(settings, plan));
        Print(settings, run);
        return run;
    }

    /// <summary>The queries, the error against the exact average, the confidence, the wall time and the files written.</summary>
    public static void Print(SupersampleRunSettings settings, SupersampleRunResult run)
    {
        var (figures, where) = (run.Figures, run.RanOn.Description);
        var (engineName, noise) = (EngineFactory.Name(settings.Engine.Kind), settings.Engine.NoiseModel);
        var error = figures.Error;
        var channels = figures.ChannelsEstimated == 1 ? "one channel (grey input), copied to R, G and B" : "R, G and B each";
        Console.WriteLine($"queries: {AtMost(settings)}{figures.QueriesPerChannel} per pixel per channel, {channels}; {AtMost(settings)}{figures.TotalQueries:N0} in all");
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"error against the exact average: mean absolute {error.MeanLevels:0.000} levels of 255 ({error.MeanFraction:0.00000}; {error.EstimatorError:0.00000} before 8-bit rounding), zero-error pixels {error.ExactPixels} of {error.Pixels} ({error.ExactShare:P1})"));
        if (figures is { MeanConfidence: { } mean, LowestConfidence: { } lowest })
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"confidence: mean {mean:0.000}, lowest {lowest:0.000} (1 = every bit plane read with certainty)"));
        Console.WriteLine($"wall time: {figures.WallTime.TotalSeconds:0.00} s on the {engineName} engine{(noise.IsNoiseless && settings.Engine.Device is null ? "" : $" under {NoiseDescription(settings)}")}; ran on {where}");
        foreach (var path in figures.Written) Console.WriteLine($"wrote {path}");
    }

    // A device model names its circuits too: it runs the single-qubit coins.
    private static string NoiseDescription(SupersampleRunSettings settings) =>
        settings.Engine.Device is { } device
            ? $"{device.Description()}{(settings.Engine.Kind == EngineKind.Analytic ? " (global depolarizing weight; exact on one qubit)" : "")}, on single-qubit coins rotated to the mean the host computes"
            : SupersamplingNoise.Description(settings.Engine.Kind, settings.Engine.NoiseModel);

    // What one estimate holds on a quantum computer: ceil(log2 N) subpixel qubits, a coin, and QSS's counter or qss-bayes's ancilla.
    private static string Registers(SupersampleSettings settings, bool singleQubitCoin)
    {
        // The device model's coins hold no subpixel register: one qubit rotated to the mean.
        var index = singleQubitCoin ? 0 : CoinRegisters.SubpixelQubits(settings.Subpixels);
        var counter = settings.Method switch
        {
            SupersampleMethod.Qss => $" + {settings.CounterBitsOrDefault} counter",
            SupersampleMethod.QssBayes => " + 1 ancilla",
            _ => "",
        };
        return settings.Method == SupersampleMethod.Mc
            ? "each query samples one random subpixel"
            : $"registers: {index} subpixel + 1 coin{counter} qubits";
    }
}
