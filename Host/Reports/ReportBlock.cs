using QuantumRayTracing.Output;

namespace QuantumRayTracing.Reports;

/// <summary>One piece of a <see cref="Report"/>, in the order it is read.</summary>
public abstract record ReportBlock;

public sealed record ReportHeading(string Text, int Level) : ReportBlock;

public sealed record ReportText(string Markdown) : ReportBlock;

public sealed record ReportTextTable(TextTable Table) : ReportBlock;

public sealed record ReportMeasureTable(ReportTable Table) : ReportBlock;

public sealed record ReportPlot(string Name, PlotSpec Spec, string Caption) : ReportBlock;

public sealed record ReportImage(string Name, RgbImage Image, string Caption) : ReportBlock;

public sealed record ReportData(TextTable Table) : ReportBlock;

/// <summary>Images side by side: one table row of pictures under their captions as column headings.</summary>
public sealed record ReportImageRow(IReadOnlyList<ReportImage> Images) : ReportBlock;
