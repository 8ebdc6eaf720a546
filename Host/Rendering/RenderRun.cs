using System.Diagnostics;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// One `render`: the scene on the chosen engine, then the classical reference with the same samples, then (with
/// sampled light) the converged classical reference; the errors between them, the images written (all or none),
/// and the figures in one record. Each stage is timed on its own.
/// </summary>
public static class RenderRun
{
    /// <summary>
    /// Runs <paramref name="settings"/>. A large render (<see cref="RenderForecast.Applies"/>) is forecast first, the forecast
    /// handed to <paramref name="onForecast"/>, and refused when its peak memory exceeds the limit.
    /// </summary>
    public static RenderRunResult Run(RenderRunSettings settings, IRunProgress? progress = null, Action<RenderForecast>? onForecast = null)
    {
        var (scene, options) = (settings.Scene, settings.Options);
        var plan = ModelledRegisters.Of(settings);
        if (RenderForecast.Applies(settings))
        {
            var forecast = RenderForecast.Of(settings);
            onForecast?.Invoke(forecast);
            forecast.EnsureFits(settings.MaxMemory ?? AvailableMemory.Bytes(), settings.MaxMemory is not null);
        }
        var clock = Stopwatch.StartNew();
        RenderResult result;
        try
        {
            result = Stage(progress, settings.Engine.Kind.Name, p => Renderer.Render(scene, settings.Engine, options, p));
        }
        catch (SimulatorLimitException e)
        {
            throw new UserError($"{scene.Name}: {e.Message}");
        }
        var renderTime = clock.Elapsed;
        LargeRenderCollection.Collect((long)options.Width * options.Height);

        clock.Restart();
        var classical = new EngineSetup(EngineKind.Classical);
        var reference = Stage(progress, "classical reference", p => Renderer.Render(scene, classical, RenderDefaults.Reference(options), p));
        var referenceTime = clock.Elapsed;

        clock.Restart();
        var converged = settings.WithConverged
            ? Stage(progress, "converged reference", p => Renderer.Render(scene, classical, settings.Converged, p))
            : null;
        var convergedTime = clock.Elapsed;

        var files = settings.Files;
        var images = new List<(RgbImage, string)> { (result.Image, files[0]) };
        if (settings.WithReference)
        {
            images.Add((reference.Image, files[1]));
            images.Add((DifferenceImage.Of(result.Image, reference.Image), files[2]));
            if (converged is not null) images.Add((converged.Image, files[3]));
        }
        ImageFiles.Write(images);

        var figures = new RenderFigures(scene.Name, plan.Primitives, options.Width, options.Height, plan.IndexQubits, plan.CoordinateBits, plan.GateRegisters,
            result.Passes, result.Total, reference.Total, ImageError.Between(result.Image, reference.Image), result.Budget,
            converged is null ? null : settings.ReferenceSamples,
            converged is null ? null : ImageError.Between(result.Image, converged.Image),
            converged is null ? null : ImageError.Between(reference.Image, converged.Image),
            renderTime, referenceTime, converged is null ? null : convergedTime, images.Select(i => i.Item2).ToArray()) { LightError = result.LightError };
        // After the render: a cluster's place counts the chunks it had to send again.
        var ranOn = EngineFactory.Place(settings.Engine.Kind, settings.Engine.Pool, settings.Engine.Workers);
        return new RenderRunResult(figures, ranOn, result, reference, converged);
    }

    private static RenderResult Stage(IRunProgress? progress, string label, Func<IRenderProgress?, RenderResult> render)
    {
        try
        {
            return render(progress?.Start(label));
        }
        finally
        {
            progress?.Finish();
        }
    }
}
