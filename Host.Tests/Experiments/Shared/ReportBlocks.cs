using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>The data tables and plots of an experiment's report, for tests of what it holds.</summary>
internal static class ReportBlocks
{
    /// <summary>The data table written as <c>&lt;report&gt;.csv</c> (no name) or <c>&lt;report&gt;-name.csv</c>.</summary>
    public static TextTable DataTable(this Report report, string? name = null) =>
        Assert.Single(report.Blocks.OfType<ReportData>(), d => d.Table.Name == name).Table;

    public static IReadOnlyList<ReportPlot> PlotBlocks(this Report report) => [.. report.Blocks.OfType<ReportPlot>()];
}
