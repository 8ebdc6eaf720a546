namespace QuantumRayTracing.Output;

/// <summary>How a command prints a <see cref="ReportTable"/>: a console table, or plain Markdown or CSV for files and pipes.</summary>
public enum ReportFormat
{
    Table,
    Md,
    Csv,
}
