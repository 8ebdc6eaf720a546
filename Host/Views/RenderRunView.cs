using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Scenes;
using Spectre.Console;

using QuantumRayTracing.Rendering;

namespace QuantumRayTracing.Views;

/// <summary>`render` on the console: what a run models before it starts, and its figures (the paper's table 1 per pass) after.</summary>
public static class RenderRunView
{
    /// <summary>What the run models, printed before it starts.</summary>
    public static void PrintModel(RenderRunSettings settings, ModelledRegisters plan)
    {
        var (scene, options) = (settings.Scene, settings.Options);
        AnsiConsole.WriteLine($"{scene.Name}: N = {plan.Primitives} primitives{Kinds(scene)}, {LightSummary(scene)}, {options.Width}x{options.Height} pixels, {scene.Grid}");
        if (scene.FramingText is { } framing)
            AnsiConsole.WriteLine($"the model framed as a scene (save it as a scene file to edit the camera, floor and light):{Environment.NewLine}{framing}");
        if (scene.Quantisation is { } quantisation)
        {
            foreach (var warning in quantisation.Warnings) Console.Error.WriteLine($"warning: {warning}");
            AnsiConsole.WriteLine($"triangles on the grid: {quantisation.Describe(scene.Grid)}; the classical reference renders the same quantised scene");
        }
        if (settings.SamplesLight)
        {
            var converged = settings.Converged;
            var area = options.Light is { } light
                ? $"area light estimated by {light.Name} with {light.Queries} queries per point and area light over a fixed set of {options.AreaSamples} samples (no shadow rays)"
                : $"{options.AreaSamples} shadow rays per point and area light";
            AnsiConsole.WriteLine($"sampled light: {(scene.AreaLights.Count > 0 ? area : "no area lights")}, {(options.Vpl > 0 ? $"{options.Vpl} VPLs per point" : "no indirect light")}; "
                + (settings.WithConverged ? $"converged reference: {converged.AreaSamples} area samples{(options.Vpl > 0 ? $", {converged.Vpl} VPLs" : "")}" : "no converged reference"));
        }
        AnsiConsole.WriteLine($"modelled per search: {plan.IndexQubits} index qubits + {plan.AuxiliaryQubits} auxiliaries, lookup table of {plan.Primitives} rows x {plan.CoordinateBits} coordinate bits per axis");
        if (settings.Engine.Kind.SearchesWithGrover)
            AnsiConsole.WriteLine($"noise model: {settings.NoiseDescription}");
        if (plan.GateRegisters is { } registers)
            AnsiConsole.WriteLine($"gate-level oracle ({OracleConstruction.Default}), centre ray: {registers.RegisterQubits} register qubits ({registers.IndexQubits} index, {1 + registers.BoundRegisters} x {registers.CoordinateQubits} coordinate, {registers.DepthQubits} depth, {registers.FlagQubits} flags, 1 phase), {registers.PeakQubits} at peak with library auxiliaries");
    }

    // " (R rectangles, T triangles)" for a scene with triangles; nothing for rectangles alone.
    private static string Kinds(Scene scene)
    {
        var rectangles = scene.Primitives.Count(p => p is Rectangle);
        return rectangles == scene.Primitives.Count ? "" : $" ({rectangles} rectangles, {scene.Primitives.Count - rectangles} triangles)";
    }

    /// <summary>The run on <paramref name="pool"/> (null: local bridges): its plan first, its progress on standard error, its figures after.</summary>
    public static RenderRunResult RunAndPrint(RenderRunSettings settings, Bridge.BridgePool? pool)
    {
        PrintModel(settings, ModelledRegisters.Of(settings));
        var run = RenderRun.Run(settings with { Engine = settings.Engine.OnBridges(pool) }, new ConsoleRunProgress(), PrintForecast);
        Print(settings, run);
        return run;
    }

    /// <summary>A large render's forecast, printed before it starts.</summary>
    public static void PrintForecast(RenderForecast forecast) =>
        AnsiConsole.WriteLine(FormattableString.Invariant(
            $"forecast: peak memory about {RenderForecast.Bytes(forecast.PeakBytes)} ({forecast.RaysPerPixel:F2} rays per pixel), at most about {forecast.Time.TotalSeconds:F0} s with the references{(forecast.ImageOnCluster ? " if this machine rendered it alone" : "")} (a line through calibration renders at {RenderForecast.CalibrationSide / 2}x{RenderForecast.CalibrationSide / 2} and {RenderForecast.CalibrationSide}x{RenderForecast.CalibrationSide} here; larger renders spend less per pixel)"));

    /// <summary>Where the run went, the cost per pass, the error against the references and the files written.</summary>
    public static void Print(RenderRunSettings settings, RenderRunResult run)
    {
        var (kind, noisy, figures) = (settings.Engine.Kind, settings.IsNoisy, run.Figures);
        var engineName = EngineFactory.Name(kind);
        AnsiConsole.WriteLine($"{engineName} ran on {run.RanOn.Description}");
        if (noisy) engineName = $"{engineName} under {settings.NoiseDescription}";
        AnsiConsole.Write(MetricsTable(engineName, figures));
        var error = figures.Error;
        var sameSamples = !settings.SamplesLight ? ""
            : settings.Options.Light is null ? " with the same samples (search error alone)"
            : " with the same samples, every one traced (search and light-estimation error)";
        AnsiConsole.WriteLine($"error against the classical render{sameSamples}: NRMSE {error.Nrmse:P2} (RMS of 8-bit channel differences / reference range), #Dpix {error.DifferentPixels}, %Dpix {error.DifferentShare:P2}");
        // Against the accuracy budget: the expected share the searches allow (docs/accuracy.md) and the measured one.
        var budget = figures.Budget;
        // An estimated light differs from every sample traced wherever the area light falls: those pixels are not search errors.
        var measured = settings.Options.Light is null ? "" : ", the light estimate's own differences included (the budget covers the searches)";
        AnsiConsole.WriteLine($"wrong pixels: expected {budget.ExpectedWrongPixels:0.0} ({budget.ExpectedShare:P3}), measured {error.DifferentPixels} ({error.DifferentShare:P3}){measured}; "
            + (budget.Share is { } share ? $"budget {share:P1}" : "no budget (its searches run as configured)"));
        if (budget.Exceeded)
            AnsiConsole.WriteLine(settings.Engine.IdealPlan
                ? $"over budget: {budget.ExpectedWrongPixels:0.0} wrong pixels expected under the noise model against {budget.Allowed:0.0} allowed, because the passes planned with the ideal miss rates (--ideal-plan)"
                : $"over budget: the expected wrong pixels stay above {budget.Allowed:0.0} after {BudgetRounds.MaxRounds} budget rounds per pass");
        AnsiConsole.WriteLine(!noisy ? "(expected: an expectation from each search path's miss rate and finds)"
            : kind.ApproximatesNoise ? "(expected: an expectation from each search path's miss rate under the noise model above, and its finds)"
            : "(expected: an expectation from each search path's ideal miss rate and finds; noise raises the share, docs/noise.md)");
        if (figures is { ConvergedError: { } toConverged, ConvergedNoise: { } monteCarlo })
            AnsiConsole.WriteLine($"error against the converged classical reference ({figures.ConvergedSamples} samples): NRMSE {toConverged.Nrmse:P2}, #Dpix {toConverged.DifferentPixels}; the classical render with the same samples: NRMSE {monteCarlo.Nrmse:P2} (Monte Carlo noise alone)");
        if (figures.LightError is { } lightError)
            AnsiConsole.WriteLine($"light error against the exact mean of its samples: NRMSE {lightError.Nrmse:P2} (RMS over every shading point's area-light irradiance channels / the exact values' range; {settings.Options.Light!.Queries} queries per point and light, a flip 1, a Grover operator 2)");
        var convergedWall = figures.ConvergedTime is { } convergedTime ? $", converged reference {convergedTime.TotalSeconds:0.00} s" : "";
        AnsiConsole.WriteLine($"wall time: {engineName} {figures.RenderTime.TotalSeconds:0.00} s, classical reference {figures.ReferenceTime.TotalSeconds:0.00} s{convergedWall}");
        AnsiConsole.MarkupLine("[grey]#Eval: conservative counts r + 1 per Grover run with r ≥ 1 (state preparation included), paper counts r (docs/conventions.md); Int/Ray = (#Eval + #C_Int) / #Rays; table rows (eval-rpc: N per ray and pass, built once and kept compact between rounds) are not in Int/Ray.[/]");
        foreach (var path in figures.Written) AnsiConsole.WriteLine($"wrote {path}");
    }

    private static Table MetricsTable(string engine, RenderFigures figures)
    {
        // Passes as columns, measures as rows: fits an 80-column terminal.
        var passes = figures.Passes.Append(figures.Total).ToArray();
        var classical = figures.ClassicalReference;
        var table = new Table().Title($"{engine}: cost per pass (paper table 1)");
        table.AddColumn("measure");
        foreach (var pass in passes) table.AddColumn(new TableColumn(pass.Name).RightAligned());
        void Row(string measure, Func<PassMetrics, string> value) => table.AddRow([measure, .. passes.Select(value)]);
        Row("#Rays", p => N(p.Rays));
        Row("#It", p => p.Iterations.ToString(CultureInfo.InvariantCulture));
        Row("#Eval, conservative", p => N(p.Cost.QueriesConservative));
        Row("#Eval, paper", p => N(p.Cost.QueriesPaper));
        Row("#C_Int", p => N(p.Cost.ClassicalTests));
        Row("#Int, conservative", p => N(p.IntersectionsConservative));
        Row("Int/Ray, conservative", p => p.PerRayConservative.ToString("0.00", CultureInfo.InvariantCulture));
        Row("Int/Ray, paper", p => p.PerRayPaper.ToString("0.00", CultureInfo.InvariantCulture));
        Row("#Cpix (neighbours)", p => N(p.UpdatedPixels));
        Row("settled classically", p => N(p.SettledRays));
        Row("table rows (eval-rpc)", p => N(p.TableRows));
        Row("wall time", p => $"{p.Elapsed.TotalSeconds:0.00} s");
        table.Caption($"classical reference: {N(classical.Rays)} rays, Int/Ray {classical.PerRayConservative:0.00}");
        return table;
    }

    private static string LightSummary(Scene scene)
    {
        var kinds = new[] { (scene.Lights.Count, "point"), (scene.AreaLights.Count, "area"), (scene.DirectionalLights.Count, "directional") }
            .Where(k => k.Item1 > 0).Select(k => $"{k.Item1} {k.Item2}").ToArray();
        return kinds.Length == 0 ? "no lights" : "lights: " + string.Join(", ", kinds);
    }

    private static string N(long value) => value.ToString("N0", CultureInfo.InvariantCulture);
}
