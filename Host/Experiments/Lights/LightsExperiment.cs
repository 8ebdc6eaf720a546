using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench lights`: the paper's sec. 7 on our renderer — the Qornell box under an area light (32 shadow rays per
/// point) and the temple's VPL indirect light (4 VPLs per point): Int/Ray of each pipeline on the quantum and
/// classical engines, the error against the classical render with the same samples (search error) and against a
/// many-sample classical reference (search error plus Monte Carlo noise), and small images of each beside its
/// references (docs/lights.md).
/// </summary>
public static class LightsExperiment
{
    public const string Title = "Area lights and indirect light (the paper's sec. 7)";

    /// <summary>One of the paper's two sec. 7 experiments.</summary>
    private sealed record Case(string Key, string Stem, string Title, string Samples, RenderOptions Options, (double Quantum, double Classical) Paper, string[] SampledPasses);

    /// <summary>A pipeline measured on one engine.</summary>
    private sealed record Row(string Name, EngineKind Engine, RenderOptions Options, QSearchOptions QSearch, bool PaperCount);

    /// <summary>The images of a case, beside the report as &lt;report&gt;-&lt;case&gt;-&lt;render&gt;.png.</summary>
    private static readonly (string Render, string Caption)[] Renders =
        [("quantum", "quantum, default pipeline"), ("classical", "classical, same samples"), ("reference", "classical, converged")];

    private static Case[] Cases(RenderOptions plain) =>
    [
        new("area", "qornell-64-area", "Area light: Qornell box 64 under a ceiling light", $"{RenderDefaults.AreaSamples} shadow rays per point",
            plain with { AreaSamples = RenderDefaults.AreaSamples }, PaperNumbers.AreaLight, [AreaLightPass.Name]),
        new("indirect", "temple-32", "Indirect light: the temple lit through its ceiling", "4 VPLs per point",
            plain with { Vpl = 4 }, PaperNumbers.IndirectLight, [IndirectPass.TraceName, IndirectPass.ShadowName]),
    ];

    /// <summary>The names of the images a run with images writes beside its report.</summary>
    public static IEnumerable<string> ImageNames => Cases(RenderOptions.PaperPipeline(1, 1)).SelectMany(c => Renders.Select(r => $"{c.Key}-{r.Render}"));

    public static Report Run(LightsSettings settings, Action<string> progress)
    {
        var (size, seed, referenceSamples) = (settings.Size, settings.Seed, settings.ReferenceSamples);
        var cases = Cases(RenderOptions.PaperPipeline(size, size, seed));
        var scenes = cases.ToDictionary(c => c.Key, c => settings.Scene(c.Stem));

        var report = new Report(Title);
        report.Text($"""
            {size}x{size} pixels, seed {seed}, analytic engine (exact outcome distributions) for the quantum rows. Classical Monte Carlo samples the light;
            the searches decide visibility. Two errors per render (NRMSE = RMS of 8-bit differences / reference range, #Dpix = pixels whose 8-bit
            RGB differs): against the classical render with **the same samples** (same seed, so the same sample positions: what the searches get
            wrong) and against the **converged** classical reference with {referenceSamples} area samples or VPLs per point (that plus Monte Carlo noise).
            *Conservative* counts r + 1 queries per Grover run, the *paper* count r with the M sets of its table 6 (docs/conventions.md).
            """);

        // A small render first on each engine, so the first measured row does not pay for JIT compilation.
        foreach (var row in Rows(cases[0].Options with { Width = 8, Height = 8 }))
            RenderMeasurement.Run(scenes[cases[0].Key], new EngineSetup(row.Engine, row.QSearch), row.Options, null);
        foreach (var c in cases)
        {
            var scene = scenes[c.Key];
            progress($"{c.Key}: references");
            var sameSamples = RenderMeasurement.Reference(scene, c.Options);
            var converged = RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Classical), RenderDefaults.Converged(c.Options, referenceSamples), null);
            report.Heading($"{c.Title} ({c.Samples}; paper: {F(c.Paper.Quantum)} Int/Ray against {F(c.Paper.Classical)} classically)");
            var table = new TextTable(c.Key, ["pipeline", "engine", "Int/Ray, conservative", "Int/Ray, paper count", .. c.SampledPasses.Select(p => $"`{p}` pass Int/Ray"),
                "NRMSE, same samples", "#Dpix, same samples", "NRMSE, converged", "#Dpix, converged", "wall time"]);
            RenderMeasurement? ours = null;
            foreach (var row in Rows(c.Options))
            {
                progress($"{c.Key}: {row.Name} on {EngineFactory.Name(row.Engine)}");
                var m = RenderMeasurement.Run(scene, new EngineSetup(row.Engine, row.QSearch), row.Options, sameSamples);
                ours ??= m;
                var toConverged = ImageError.Between(m.Result.Image, converged.Result.Image);
                var passes = c.SampledPasses.Select(name => m.Result.Passes.Single(p => p.Name == name))
                    .Select(p => F(row.PaperCount ? p.PerRayPaper : p.PerRayConservative));
                table.Row([row.Name, EngineFactory.Name(row.Engine), F(m.Result.Total.PerRayConservative), F(m.Result.Total.PerRayPaper), .. passes,
                    P(m.Error.Nrmse), N(m.Error.DifferentPixels), P(toConverged.Nrmse), N(toConverged.DifferentPixels), Seconds(m.WallTime)]);
            }
            table.Row([$"converged reference, {referenceSamples} samples", "classical", F(converged.Result.Total.PerRayConservative), F(converged.Result.Total.PerRayPaper),
                .. c.SampledPasses.Select(_ => ""), "", "", P(0), "0", Seconds(converged.WallTime)]);
            report.Table(table);
            report.Text("Default quantum pipeline, per pass (conservative count):");
            report.Table(PassTable(c.Key, ours!));

            // Images at a small size: our default pipeline, the classical render with its samples, the converged reference.
            if (settings.ImageSize is not { } imageSize) continue;
            progress($"{c.Key}: images");
            var small = c.Options with { Width = imageSize, Height = imageSize };
            var quantum = RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic), Default(small), null);
            var classical = RenderMeasurement.Reference(scene, small);
            var reference = RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Classical), RenderDefaults.Converged(small, referenceSamples), null);
            report.Text($"""
                {imageSize}x{imageSize}: our default quantum pipeline, the classical render with the same samples, the converged classical reference ({referenceSamples} samples);
                NRMSE against the converged reference {P(ImageError.Between(quantum.Result.Image, reference.Result.Image).Nrmse)} (quantum) and {P(ImageError.Between(classical.Result.Image, reference.Result.Image).Nrmse)} (classical, same samples).
                """);
            RenderMeasurement[] images = [quantum, classical, reference];
            report.ImageRow([.. Renders.Zip(images, (r, m) => new ReportImage($"{c.Key}-{r.Render}", m.Result.Image, r.Caption))]);
        }
        report.Text($"""
            Rows: *default* is `render` with no options but the sample count (NeighOpt, occluder gathering with a layout channel per light and sample
            or VPL index, exact termination, a lattice of {RenderDefaults.LatticeLevelsFor(size, size)} levels with cheap confirmations where neighbours agree; the VPL shadow pass runs without
            termination, see docs/rendering.md); *paper's configuration* is NeighOpt on primary and specular rays with the paper's termination and up to 8
            rounds, in the paper's count (as in optimised-tracing.md's table 7); *no optimisation* is 4 TracePass and 2 DirectPass rounds. The classical
            engine through our default pipeline shows what the pipeline alone saves (docs/conventions.md); plain classical costs N per ray. The paper's
            configuration ends shadow rays by the termination criterion too but gathers no occluders, so a shadow ray whose one search missed its
            occluder usually stays lit: that is where its wrong pixels come from (with occluder gathering its area-light error falls to the default's).
            """);
        return report;
    }

    // Our default pipeline: what `render` uses with no options.
    private static RenderOptions Default(RenderOptions options) => RenderDefaults.Options(options.Width, options.Height, options.Seed) with
    {
        AreaSamples = options.AreaSamples, Vpl = options.Vpl,
    };

    private static Row[] Rows(RenderOptions options)
    {
        var ours = new QSearchOptions();
        var paper = new QSearchOptions(Rule: MSetRule.Round);
        return
        [
            new("default", EngineKind.Analytic, Default(options), ours, false),
            new("paper's configuration", EngineKind.Analytic, options with { Iterations = 8, Neighbours = true, Stop = StopMode.Paper }, paper, true),
            new("no optimisation", EngineKind.Analytic, options, ours, false),
            new("default", EngineKind.Classical, Default(options), ours, false),
            new("plain", EngineKind.Classical, options, ours, false),
        ];
    }

    // #Rays, Int/Ray and #Cpix of every pass of the default quantum pipeline (the first row), conservative count.
    private static TextTable PassTable(string key, RenderMeasurement m)
    {
        var passes = m.Result.Passes.Where(p => p.Rays > 0).Append(m.Result.Total).ToArray();
        return new TextTable($"{key}-passes", ["", .. passes.Select(p => p.Name)])
            .Row(["#Rays", .. passes.Select(p => p.Rays.ToString("N0", CultureInfo.InvariantCulture))])
            .Row(["Int/Ray", .. passes.Select(p => F(p.PerRayConservative))])
            .Row(["#Cpix", .. passes.Select(p => p.UpdatedPixels.ToString("N0", CultureInfo.InvariantCulture))]);
    }

    private static string F(double value) => value.ToString("0.0", CultureInfo.InvariantCulture);

    private static string N(long value) => value.ToString(CultureInfo.InvariantCulture);

    private static string P(double value) => value.ToString("P2", CultureInfo.InvariantCulture);

    private static string Seconds(TimeSpan time) => time.TotalSeconds.ToString("0.0 s", CultureInfo.InvariantCulture);
}
