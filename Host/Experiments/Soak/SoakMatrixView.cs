using QuantumRayTracing.Engines;
using Spectre.Console;

namespace QuantumRayTracing.Experiments;

/// <summary>A soak on the console: scenes by engines, so the table fits 80 columns, then the reasons of every row that is not ok.</summary>
public static class SoakMatrixView
{
    public static void Print(SoakResult result)
    {
        var rows = result.Rows;
        var engineKinds = rows.Where(r => r.Engine is not null).Select(r => r.Engine!.Value).Distinct().ToArray();
        var table = new Table().Title("soak: scenes by engines");
        table.AddColumn("scene");
        foreach (var kind in engineKinds) table.AddColumn(EngineFactory.Name(kind));
        foreach (var scene in rows.GroupBy(r => r.Scene))
            table.AddRow([Markup.Escape($"{scene.Key}\nN = {scene.First().Primitives}"),
                .. engineKinds.Select(k => scene.FirstOrDefault(r => r.Engine == k) is { } row ? Markup.Escape(SoakReport.MatrixCell(row)) : "")]);
        AnsiConsole.Write(table);
        foreach (var row in rows.Where(r => r.Status != SoakStatus.Ok))
            AnsiConsole.WriteLine($"{row.Scene}{(row.Engine is { } e ? " on " + EngineFactory.Name(e) : "")}: {row.StatusText}");
        AnsiConsole.WriteLine($"{SoakReport.Summary(rows)}; {result.Total.TotalSeconds:0.0} s");
    }
}
