using System.Diagnostics;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What a soak found: a row per scene and engine, the wall time of the whole soak, the qsharp-lang and Node versions
/// of the bridges (nulls when no simulator ran) and the report (docs/soak.md).
/// </summary>
public sealed record SoakResult(IReadOnlyList<SoakRow> Rows, TimeSpan Total, (string? QSharp, string? Node) Versions, Report Report)
{
    /// <summary>Whether any render failed a check.</summary>
    public bool Failed => Rows.Any(r => r.Status == SoakStatus.Failed);
}

/// <summary>`bench soak`: every scene file on every engine with every seed, each render checked (<see cref="Soak"/>), and its report.</summary>
public static class SoakExperiment
{
    /// <summary>
    /// Soaks <paramref name="sceneFiles"/> with <paramref name="settings"/>; <paramref name="progress"/> gets a label
    /// per render, <paramref name="onRow"/> each finished row.
    /// </summary>
    public static SoakResult Run(IReadOnlyList<string> sceneFiles, SoakSettings settings, Func<string, IRenderProgress?>? progress = null, Action<SoakRow>? onRow = null)
    {
        var clock = Stopwatch.StartNew();
        using var engines = new SoakEngines(settings.Workers, settings.MaxQubits, settings.Pool);
        var rows = Soak.Run(sceneFiles, settings, engines.Render, progress, onRow);
        var total = clock.Elapsed;
        return new SoakResult(rows, total, engines.Versions(), SoakReport.Of(rows, settings, total));
    }
}
