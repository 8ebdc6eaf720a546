using System.Text;
using System.Text.Json.Nodes;
using Spectre.Console;

namespace QuantumRayTracing.Output;

/// <summary>
/// A table of measures (rows) by subjects (columns) with a title, context lines above it and notes
/// below, written as a Spectre console table, Markdown or CSV. The same content in every form, so
/// what the console shows is what a file records.
/// </summary>
public sealed class ReportTable(string title, string corner, IReadOnlyList<string> columns)
{
    private readonly List<(string Measure, string[] Values)> _rows = [];
    private readonly List<string> _context = [];
    private readonly List<string> _notes = [];

    public string Title => title;

    public IReadOnlyList<string> Columns => columns;

    public IReadOnlyList<(string Measure, string[] Values)> Rows => _rows;

    public ReportTable Context(string line)
    {
        _context.Add(line);
        return this;
    }

    public ReportTable Row(string measure, IEnumerable<string> values)
    {
        var cells = values.ToArray();
        if (cells.Length != columns.Count) throw new ArgumentException($"row '{measure}' has {cells.Length} values for {columns.Count} columns");
        _rows.Add((measure, cells));
        return this;
    }

    public ReportTable Note(string line)
    {
        _notes.Add(line);
        return this;
    }

    /// <summary>Prints the table to standard output: a console table, Markdown or CSV.</summary>
    public void Write(ReportFormat format)
    {
        switch (format)
        {
            case ReportFormat.Md:
                Console.Write(ToMarkdown());
                break;
            case ReportFormat.Csv:
                Console.Write(ToCsv());
                break;
            default:
                WriteToConsole();
                break;
        }
    }

    public void WriteToConsole()
    {
        foreach (var line in _context) AnsiConsole.WriteLine(line);
        var table = new Table().Title(Markup.Escape(title));
        table.AddColumn(Markup.Escape(corner));
        foreach (var column in columns) table.AddColumn(new TableColumn(Markup.Escape(column)).RightAligned());
        foreach (var (measure, values) in _rows) table.AddRow([Markup.Escape(measure), .. values.Select(Markup.Escape)]);
        AnsiConsole.Write(table);
        foreach (var note in _notes) AnsiConsole.MarkupLine($"[grey]{Markup.Escape(note)}[/]");
    }

    public string ToMarkdown(string heading = "###")
    {
        var text = new StringBuilder();
        text.AppendLine($"{heading} {title}").AppendLine();
        foreach (var line in _context) text.AppendLine($"- {line}");
        if (_context.Count > 0) text.AppendLine();
        text.AppendLine($"| {Cell(corner)} | {string.Join(" | ", columns.Select(Cell))} |");
        text.AppendLine($"|---|{string.Concat(columns.Select(_ => "---:|"))}");
        foreach (var (measure, values) in _rows) text.AppendLine($"| {Cell(measure)} | {string.Join(" | ", values.Select(Cell))} |");
        if (_notes.Count > 0) text.AppendLine();
        foreach (var note in _notes) text.AppendLine($"- {note}");
        return text.ToString();
    }

    /// <summary>The same content as JSON: title, context, the corner and columns, rows of measure and cells, notes.</summary>
    public JsonObject ToJson() => new()
    {
        ["title"] = title,
        ["context"] = new JsonArray([.. _context.Select(l => JsonValue.Create(l))]),
        ["corner"] = corner,
        ["columns"] = new JsonArray([.. columns.Select(c => JsonValue.Create(c))]),
        ["rows"] = new JsonArray([.. _rows.Select(r => new JsonObject
        {
            ["measure"] = r.Measure,
            ["values"] = new JsonArray([.. r.Values.Select(v => JsonValue.Create(v))]),
        })]),
        ["notes"] = new JsonArray([.. _notes.Select(l => JsonValue.Create(l))]),
    };

    /// <summary>RFC 4180 rows; the title, context and notes as leading lines starting with '#'.</summary>
    public string ToCsv()
    {
        var text = new StringBuilder();
        foreach (var line in new[] { title }.Concat(_context).Concat(_notes)) text.AppendLine($"# {line}");
        text.AppendLine(string.Join(',', new[] { corner }.Concat(columns).Select(Quote)));
        foreach (var (measure, values) in _rows) text.AppendLine(string.Join(',', new[] { measure }.Concat(values).Select(Quote)));
        return text.ToString();
    }

    private static string Cell(string text) => text.Replace("|", "\\|", StringComparison.Ordinal);

    private static string Quote(string text) =>
        text.IndexOfAny([',', '"', '\n', '\r']) >= 0 ? $"\"{text.Replace("\"", "\"\"", StringComparison.Ordinal)}\"" : text;
}
