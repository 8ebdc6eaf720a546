using System.Text;

namespace QuantumRayTracing.Reports;

/// <summary>
/// A table of formatted cells under a header row, written as Markdown or RFC 4180 CSV. <paramref name="name"/>
/// (a file-name fragment such as "table-2") names its CSV file; an unnamed table is shown but not written as CSV.
/// </summary>
public sealed class TextTable(string? name, IReadOnlyList<string> header)
{
    private readonly List<string[]> _rows = [];
    private readonly HashSet<int> _rightAligned = [];

    public string? Name => name;

    public IReadOnlyList<string> Header => header;

    public IReadOnlyList<string[]> Rows => _rows;

    public TextTable Row(params IEnumerable<string> cells)
    {
        var row = cells.ToArray();
        if (row.Length != header.Count) throw new ArgumentException($"a row of {row.Length} cells under {header.Count} columns");
        _rows.Add(row);
        return this;
    }

    /// <summary>Right-aligns the Markdown columns at <paramref name="columns"/> (0-based), for numbers.</summary>
    public TextTable AlignRight(params IEnumerable<int> columns)
    {
        _rightAligned.UnionWith(columns);
        return this;
    }

    public string ToMarkdown()
    {
        var text = new StringBuilder();
        text.AppendLine($"| {string.Join(" | ", header.Select(Cell))} |");
        text.AppendLine($"|{string.Concat(header.Select((_, k) => _rightAligned.Contains(k) ? "---:|" : "---|"))}");
        foreach (var row in _rows) text.AppendLine($"| {string.Join(" | ", row.Select(Cell))} |");
        return text.ToString();
    }

    public string ToCsv()
    {
        var text = new StringBuilder();
        foreach (var row in _rows.Prepend([.. header])) text.AppendLine(string.Join(',', row.Select(Quote)));
        return text.ToString();
    }

    private static string Cell(string text) => text.Replace("|", "\\|", StringComparison.Ordinal);

    private static string Quote(string text) =>
        text.IndexOfAny([',', '"', '\n', '\r']) >= 0 ? $"\"{text.Replace("\"", "\"\"", StringComparison.Ordinal)}\"" : text;
}
