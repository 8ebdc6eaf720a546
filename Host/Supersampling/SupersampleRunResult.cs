using QuantumRayTracing.Estimation;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Supersampling;

/// <summary>
/// A finished <see cref="SupersampleRun"/>: the figures `supersample` prints and records, where the engine ran, the
/// input with its subpixels and the estimate itself.
/// </summary>
public sealed record SupersampleRunResult(SupersampleFigures Figures, RunPlace RanOn, SubpixelImage Input, SupersampleResult Estimate);
