using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Output;

/// <summary>The same table as Markdown and CSV: every cell, context line and note, escaped for its format.</summary>
public sealed class ReportTableTests
{
    private static ReportTable Sample() => new ReportTable("Costs", "measure", ["oracle", "run, r = 2"])
        .Context("scene: a | b")
        .Row("qubits", ["25", "25"])
        .Row("a|b", ["1", "2"])
        .Row("gates \"native\"", ["876", "1,752"])
        .Note("counted once");

    [Fact]
    public void MarkdownHasOneColumnPerSubjectAndEscapesPipesInCells()
    {
        var lines = Sample().ToMarkdown().Split(Environment.NewLine);
        Assert.Equal("### Costs", lines[0]);
        Assert.Contains("- scene: a | b", lines); // a list item, not a cell: no escape needed
        Assert.Contains("| measure | oracle | run, r = 2 |", lines);
        Assert.Contains("|---|---:|---:|", lines);
        Assert.Contains("| gates \"native\" | 876 | 1,752 |", lines);
        Assert.Contains(@"| a\|b | 1 | 2 |", lines);
        Assert.Contains("- counted once", lines);
    }

    [Fact]
    public void CsvQuotesFieldsWithCommasAndQuotes()
    {
        var lines = Sample().ToCsv().Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal(["# Costs", "# scene: a | b", "# counted once"], lines[..3]);
        Assert.Equal("measure,oracle,\"run, r = 2\"", lines[3]);
        Assert.Equal("qubits,25,25", lines[4]);
        Assert.Equal("a|b,1,2", lines[5]);
        Assert.Equal("\"gates \"\"native\"\"\",876,\"1,752\"", lines[6]);
    }

    [Fact]
    public void RowWithTheWrongNumberOfValuesIsRejected() =>
        Assert.Throws<ArgumentException>(() => new ReportTable("t", "m", ["a", "b"]).Row("x", ["1"]));
}
