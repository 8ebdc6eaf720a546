using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>The named tables of an experiment's report, for tests that read its cells.</summary>
internal static class ReportTables
{
    public static TextTable Table(this Report report, string name) =>
        Assert.Single(report.Blocks.OfType<ReportTextTable>(), t => t.Table.Name == name).Table;

    /// <summary>The cell of <paramref name="row"/> under the <paramref name="column"/>-th heading named <paramref name="heading"/>.</summary>
    public static string Cell(this TextTable table, string[] row, string heading, int column = 0) =>
        row[table.Header.Select((h, i) => (h, i)).Where(c => c.h == heading).ElementAt(column).i];
}
