using System.Text;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Reports;

/// <summary>
/// Writes a <see cref="Report"/>: Markdown to <paramref name="markdownPath"/> (opened by a marker naming
/// <paramref name="command"/>, so a later run replaces only its own file), every plot and image as a PNG beside it,
/// every data table as CSV beside it, and with <paramref name="tablesAsCsv"/> every named table too. With no path the
/// Markdown is printed only. Every file is checked before any is written, and all are written or none.
/// </summary>
public sealed class ReportWriter(string? markdownPath, string command, bool tablesAsCsv = false)
{
    private readonly GeneratedReport _markdown = new(markdownPath, GeneratedReport.MarkdownMarker(command));

    private string FullPath => Path.GetFullPath(markdownPath ?? "report");

    /// <summary>Fails with a one-line <see cref="UserError"/> when the Markdown file may not be written; call it before the work.</summary>
    public void EnsureWritable() => _markdown.EnsureWritable();

    /// <summary>
    /// Also checks the PNG files the report will write beside its Markdown, named as its plots and images are
    /// (<paramref name="pictures"/>), so a file we did not write stops the run before the work, not after it.
    /// </summary>
    public void EnsureWritable(IEnumerable<string> pictures)
    {
        EnsureWritable();
        if (markdownPath is not null) ImageFiles.EnsureWritable([.. pictures.Select(name => Beside(name, ".png"))], []);
    }

    /// <summary>The PNG or CSV file beside the Markdown for a block named <paramref name="name"/> (empty: the report's own stem).</summary>
    public string Beside(string name, string extension) =>
        Path.ChangeExtension(name.Length == 0 ? FullPath : ImageFiles.Beside(FullPath, name), extension);

    /// <summary>Checks the CSV files of the report's data tables named <paramref name="data"/> ("" for the unnamed one) before the work.</summary>
    public void EnsureDataWritable(IEnumerable<string> data)
    {
        if (markdownPath is null) return;
        foreach (var name in data) new GeneratedReport(Beside(name, ".csv"), CsvMarker(command)).EnsureWritable();
    }

    /// <summary>The report as Markdown, with <paramref name="footer"/> lines (machine, command) at its end.</summary>
    public string Markdown(Report report, IEnumerable<string> footer)
    {
        var text = new StringBuilder();
        text.AppendLine($"# {report.Title}").AppendLine();
        foreach (var block in report.Blocks)
        {
            switch (block)
            {
                case ReportHeading h: text.AppendLine($"{new string('#', h.Level)} {h.Text}").AppendLine(); break;
                case ReportText t: text.AppendLine(t.Markdown.TrimEnd()).AppendLine(); break;
                case ReportTextTable t: text.Append(t.Table.ToMarkdown()).AppendLine(); break;
                case ReportMeasureTable t: text.Append(t.Table.ToMarkdown()).AppendLine(); break;
                case ReportPlot p: text.AppendLine(Picture(p.Name, p.Caption)).AppendLine(); break;
                case ReportImage i: text.AppendLine(Picture(i.Name, i.Caption)).AppendLine(); break;
                case ReportImageRow r: text.Append(ImageRow(r)).AppendLine(); break;
                case ReportData: break;
                default: throw new ArgumentOutOfRangeException(nameof(report), block, "a report block this writer does not know");
            }
        }
        foreach (var line in footer) text.AppendLine(line);
        return text.ToString();
    }

    /// <summary>Prints the Markdown (unless <paramref name="print"/> is false) and, with a path, writes it with its PNG and CSV files.</summary>
    public void Write(Report report, IEnumerable<string> footer, bool print = true)
    {
        var markdown = Markdown(report, footer);
        if (print) Console.WriteLine(markdown);
        if (markdownPath is null) return;

        var images = new List<(RgbImage Image, string Path)>();
        var csv = new List<(string Path, string Text)>();
        foreach (var block in report.Blocks)
        {
            switch (block)
            {
                case ReportPlot p: images.Add((PlotImage.Render(p.Spec), Beside(p.Name, ".png"))); break;
                case ReportImage i: images.Add((i.Image, Beside(i.Name, ".png"))); break;
                case ReportImageRow r: images.AddRange(r.Images.Select(i => (i.Image, Beside(i.Name, ".png")))); break;
                case ReportData d: csv.Add((Beside(d.Table.Name ?? "", ".csv"), d.Table.ToCsv())); break;
                case ReportTextTable { Table.Name: { } name } t when tablesAsCsv: csv.Add((Beside(name, ".csv"), t.Table.ToCsv())); break;
            }
        }
        var csvFiles = csv.Select(c => new GeneratedReport(c.Path, CsvMarker(command))).ToArray();
        ImageFiles.EnsureWritable(images.Select(i => i.Path).ToArray(), []);
        foreach (var file in csvFiles) file.EnsureWritable();
        _markdown.EnsureWritable();

        var utf8 = new UTF8Encoding(false);
        (string, byte[])[] files =
        [
            .. images.Select(i => (i.Path, PngWriter.Encode(i.Image))),
            .. csv.Select((c, k) => (c.Path, utf8.GetBytes(csvFiles[k].Compose(c.Text)))),
            (markdownPath, utf8.GetBytes(_markdown.Compose(markdown))),
        ];
        try
        {
            AtomicFile.WriteAll(files);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new UserError($"{markdownPath}: the report and its files cannot be written: {e.Message}");
        }
    }

    /// <summary>The first line of a CSV file this command generates.</summary>
    public static string CsvMarker(string command) => $"# generated by `{command}`";

    private string ImageRow(ReportImageRow row) => new TextTable(null, [.. row.Images.Select(i => i.Caption)])
        .Row(row.Images.Select(i => Picture(i.Name, i.Caption, alt: Path.GetFileNameWithoutExtension(Beside(i.Name, ".png")))))
        .ToMarkdown();

    /// <summary>The Markdown that shows a PNG of the report; <paramref name="alt"/> defaults to the caption.</summary>
    private string Picture(string name, string caption, string? alt = null) => markdownPath is null
        ? $"({caption}: a PNG written with --output)"
        : $"![{alt ?? caption}]({Path.GetFileName(Beside(name, ".png"))})";
}
