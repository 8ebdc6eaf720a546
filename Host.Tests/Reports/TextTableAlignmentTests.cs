using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Tests.Reports;

public sealed class TextTableAlignmentTests
{
    [Fact]
    public void RightAlignedColumnsGetAColonInTheMarkdownOnly()
    {
        var table = new TextTable("t", ["name", "count", "note"]).AlignRight(1).Row("a", "12", "x");
        Assert.Equal("| name | count | note |\n|---|---:|---|\n| a | 12 | x |\n", table.ToMarkdown().ReplaceLineEndings("\n"));
        Assert.Equal("name,count,note\na,12,x\n", table.ToCsv().ReplaceLineEndings("\n"));
    }
}
