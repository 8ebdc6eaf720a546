using QuantumRayTracing.Output;

namespace QuantumRayTracing.Reports;

/// <summary>
/// What an experiment returns: its title and an ordered list of blocks (headings, text, tables, plots,
/// images and data tables), free of any file or console. <see cref="ReportWriter"/> turns it into Markdown,
/// CSV and PNG files; the experiments behind `bench` build one each.
/// </summary>
public sealed class Report(string title)
{
    private readonly List<ReportBlock> _blocks = [];

    public string Title => title;

    public IReadOnlyList<ReportBlock> Blocks => _blocks;

    /// <summary>A section heading; <paramref name="level"/> 2 is "##".</summary>
    public Report Heading(string text, int level = 2) => Add(new ReportHeading(text, level));

    /// <summary>A paragraph of Markdown; several lines stay one paragraph.</summary>
    public Report Text(string markdown) => Add(new ReportText(markdown));

    /// <summary>A Markdown table; it is written as CSV too when it has a name.</summary>
    public Report Table(TextTable table) => Add(new ReportTextTable(table));

    /// <summary>A measures-by-subjects table, as the commands print it.</summary>
    public Report Table(ReportTable table) => Add(new ReportMeasureTable(table));

    /// <summary>A plot drawn to <c>&lt;report&gt;-<paramref name="name"/>.png</c> and shown with <paramref name="caption"/>.</summary>
    public Report Plot(string name, PlotSpec spec, string caption) => Add(new ReportPlot(name, spec, caption));

    /// <summary>An image written to <c>&lt;report&gt;-<paramref name="name"/>.png</c> and shown with <paramref name="caption"/>.</summary>
    public Report Image(string name, RgbImage image, string caption) => Add(new ReportImage(name, image, caption));

    /// <summary>
    /// Images side by side, each written to <c>&lt;report&gt;-name.png</c>: a table whose headings are the captions
    /// and whose one row shows the pictures, each named by its file.
    /// </summary>
    public Report ImageRow(IReadOnlyList<ReportImage> images) => Add(new ReportImageRow(images));

    /// <summary>
    /// Data for scripts, written only as CSV: <c>&lt;report&gt;.csv</c> when <paramref name="table"/> has no
    /// name, <c>&lt;report&gt;-name.csv</c> otherwise; the Markdown does not show it.
    /// </summary>
    public Report Data(TextTable table) => Add(new ReportData(table));

    private Report Add(ReportBlock block)
    {
        _blocks.Add(block);
        return this;
    }
}
