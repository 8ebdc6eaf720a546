using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Passes;

/// <summary>
/// How a pass iterates: at most <see cref="Iterations"/> rounds (#IT); <see cref="Neighbours"/>, when
/// set, the layout NeighOpt gathers over after each round; <see cref="Stop"/>, when set, the sec. 6.2
/// termination criterion deciding after each empty search whether a ray is searched again.
/// </summary>
public sealed record PassOptions(int Iterations, TieBreak TieBreak = TieBreak.Strict, PixelLayout? Neighbours = null, StopRule? Stop = null);
