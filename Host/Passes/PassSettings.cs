using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Passes;

/// <summary>
/// What the passes read of a render's options: the image they lay rays out on, the TracePass and DirectPass rounds, ties,
/// gathering, whether an accuracy budget holds the render, the light's samples and how the area light is read, and the seed
/// their own draws fork from. The render builds it from its options.
/// </summary>
public sealed record PassSettings(
    int Width,
    int Height,
    int Iterations,
    int ShadowIterations,
    TieBreak TieBreak,
    bool Neighbours,
    bool ShadowNeighbours,
    bool Budgeted,
    int AreaSamples,
    int Vpl,
    ulong Seed,
    LightEstimation? Light);
