using QuantumRayTracing.Intersection;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Passes;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// Everything `render` prints about a run, in one record its text and its --json file are both written from:
/// the scene and what a search models (index qubits, coordinate bits; with the gate engine the centre ray's oracle
/// registers), each pass's metrics and their total (docs/conventions.md), the classical reference's, the error
/// against it and the accuracy budget's expected wrong pixels, with sampled light the error against the converged reference and that reference's own Monte Carlo
/// noise, the wall times and the files written.
/// </summary>
public sealed record RenderFigures(
    string Scene,
    int Primitives,
    int Width,
    int Height,
    int IndexQubits,
    int CoordinateBits,
    OracleRegisters? GateRegisters,
    IReadOnlyList<PassMetrics> Passes,
    PassMetrics Total,
    PassMetrics ClassicalReference,
    ImageError Error,
    AccuracyBudget Budget,
    int? ConvergedSamples,
    ImageError? ConvergedError,
    ImageError? ConvergedNoise,
    TimeSpan RenderTime,
    TimeSpan ReferenceTime,
    TimeSpan? ConvergedTime,
    IReadOnlyList<string> Written)
{
    /// <summary>With estimated light, its error against the exact mean of each point's samples (<see cref="RenderOptions.Light"/>); otherwise null.</summary>
    public LightError? LightError { get; init; }
}
