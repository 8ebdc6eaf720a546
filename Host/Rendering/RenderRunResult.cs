using QuantumRayTracing.Output;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// A finished <see cref="RenderRun"/>: the figures `render` prints and records, where the searches ran, and the
/// renders themselves (the engine's, the classical reference, and with sampled light the converged reference).
/// </summary>
public sealed record RenderRunResult(RenderFigures Figures, RunPlace RanOn, RenderResult Render, RenderResult Reference, RenderResult? Converged);
