using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Tests.Benchmarks;

/// <summary>Finds the blocks of a <see cref="Report"/> an experiment returned, for tests of what it holds.</summary>
internal static class ReportLookup
{
    public static TextTable Table(this Report report, string name) =>
        report.Blocks.OfType<ReportTextTable>().Select(t => t.Table).Single(t => t.Name == name);

    public static TextTable Data(this Report report, string? name = null) =>
        report.Blocks.OfType<ReportData>().Select(d => d.Table).Single(t => t.Name == name);

    public static IReadOnlyList<ReportPlot> Plots(this Report report) => [.. report.Blocks.OfType<ReportPlot>()];

    /// <summary>The cell of <paramref name="table"/> in the row whose first cell is <paramref name="key"/> and the column headed <paramref name="column"/>.</summary>
    public static string Cell(this TextTable table, string key, string column) =>
        table.Rows.Single(r => r[0] == key)[IndexOf(table, column)];

    public static int IndexOf(this TextTable table, string column)
    {
        var index = table.Header.ToList().IndexOf(column);
        Assert.True(index >= 0, $"no column '{column}' in table {table.Name}");
        return index;
    }
}
