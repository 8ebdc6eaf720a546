namespace QuantumRayTracing.Export;

/// <summary>One `qrt export`: what to write, in which format, where (null: standard output), and whether an existing file may be replaced.</summary>
public sealed record ExportSettings(ExportSubject Subject, ExportFormat Format, string? Output, bool Force);
