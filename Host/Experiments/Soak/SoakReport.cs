using System.Globalization;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Experiments;

/// <summary>A soak's rows as table cells, and as the report `bench soak -o` writes (docs/soak.md).</summary>
public static class SoakReport
{
    public static readonly string[] Columns =
        ["scene", "N", "engine", "size", "renders", "wall time / render", "Int/Ray", "NRMSE (worst seed)", "#Dpix (worst seed) / bound", "same seed, same bytes", "another seed changes", "status"];

    /// <summary>The cells of <paramref name="row"/>, in <see cref="Columns"/> order.</summary>
    public static string[] Cells(SoakRow row)
    {
        if (row.Engine is not { } kind) return [row.Scene, "", "", "", "", "", "", "", "", "", "", row.StatusText];
        var ran = row.Renders > 0;
        return
        [
            row.Scene,
            row.Primitives.ToString(CultureInfo.InvariantCulture),
            EngineFactory.Name(kind),
            ran ? $"{row.Size}x{row.Size}" : "",
            ran ? row.Renders.ToString(CultureInfo.InvariantCulture) : "",
            ran ? Time(row.WallTime) : "",
            row.IntPerRay is { } perRay ? perRay.ToString("0.0", CultureInfo.InvariantCulture) : "",
            row.Nrmse is { } nrmse ? nrmse.ToString("P2", CultureInfo.InvariantCulture) : "",
            row.DifferentPixels is { } dpix ? dpix.ToString(CultureInfo.InvariantCulture) + (row.PixelBound is { } bound ? $" / {bound}" : "") : "",
            !ran ? "" : row.Deterministic switch { true => "yes", false => "NO", null => "n.a. (unseedable)" },
            row.SeedEffect,
            row.StatusText,
        ];
    }

    /// <summary>
    /// A row's cell in the console's matrix of scenes by engines: its status, then #Dpix against its bound
    /// (or NRMSE where there is none) and the wall time per render; the reasons are listed below the matrix.
    /// </summary>
    public static string MatrixCell(SoakRow row)
    {
        var status = row.Status switch { SoakStatus.Ok => "ok", SoakStatus.Failed => "FAILED", _ => "skipped" };
        if (row.Renders == 0) return status;
        var cells = Cells(row);
        var error = row.PixelBound is null ? "NRMSE " + cells[7] : "#Dpix " + cells[8];
        return $"{status}\n{error}\n{cells[5]}";
    }

    /// <summary>"12 ok, 1 FAILED, 3 skipped".</summary>
    public static string Summary(IReadOnlyList<SoakRow> rows) =>
        $"{rows.Count(r => r.Status == SoakStatus.Ok)} ok, {rows.Count(r => r.Status == SoakStatus.Failed)} FAILED, {rows.Count(r => r.Status == SoakStatus.Skipped)} skipped";

    public const string Title = "Soak: every scene on every engine";

    /// <summary>The report: what was run and checked, the table and the summary.</summary>
    public static Report Of(IReadOnlyList<SoakRow> rows, SoakSettings settings, TimeSpan total)
    {
        var report = new Report(Title);
        report.Text($"""
            Every scene file rendered on {string.Join(", ", settings.Engines.Select(EngineFactory.Name))} with seeds {string.Join(" and ", settings.Seeds)}
            through `render`'s default pipeline without its accuracy budget (on the smallest scenes, such as qornell-8, the budget settles every ray classically, and a seed would have nothing left to change) at {settings.Size}x{settings.Size} pixels (the gate engine at {settings.GateSize}x{settings.GateSize}), {settings.Iterations} TracePass and {settings.ShadowIterations} DirectPass rounds,
            {settings.AreaSamples} area samples and {settings.Vpl} VPLs per point. Each render is checked: no exception; finite radiance and a PNG that
            decodes to its pixels; the classical engine equal to the classical reference, the quantum engines (analytic, fullstate,
            gate) at most the #Dpix bound from it (the {1 - DifferentPixelBound.FalseFailure:0.######} quantile of Binomial(pixels, {DifferentPixelBound.Rate})); the seedable engines
            (classical, randomized, analytic) render each seed twice and must give the same PNG bytes at the same search cost;
            another seed must change the analytic and randomized renders (the image, or where the seeds give the same image, the
            search cost) and the classical image exactly when the scene samples light. The fullstate and gate engines cannot be
            seeded. The gate engine skips a render forecast to take over {settings.GateBudget.TotalSeconds:0} s (rays x N^2.5 x {GateCostEstimate.SecondsPerRayUnit * 1e6:0} µs) and a search
            wider than its qubit limit{(settings.SimulatorsOnSmallestSceneOnly ? "; in this short form fullstate and gate run on the smallest scene only." : ".")}
            Int/Ray is the conservative count averaged over the seeds; wall time is per render. See [reliability.md](reliability.md).
            """);
        var table = new TextTable("soak", Columns);
        foreach (var row in rows) table.Row(Cells(row));
        report.Table(table);
        report.Text($"{Summary(rows)}; {Time(total)} in all.");
        return report;
    }

    private static string Time(TimeSpan time) => time.TotalSeconds < 100
        ? time.TotalSeconds.ToString("0.00", CultureInfo.InvariantCulture) + " s"
        : time.TotalMinutes.ToString("0.0", CultureInfo.InvariantCulture) + " min";
}
