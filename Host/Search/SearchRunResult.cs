using QuantumRayTracing.Output;

namespace QuantumRayTracing.Search;

/// <summary>A finished <see cref="SearchRun"/>: the figures `search` prints and records, and where the engine ran.</summary>
public sealed record SearchRunResult(SearchFigures Figures, RunPlace RanOn);
