using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// What `estimate --frame` prices: the frame (scene, render options with size and seed, QSearch's
/// options), the oracle construction the runs are estimated with, the qubit models, the frame's error
/// budget ε and the quantum processors K of the parallel runtime.
/// </summary>
public sealed record FrameSettings(
    Scene Scene,
    RenderOptions Render,
    QSearchOptions Search,
    OracleConstruction Construction,
    IReadOnlyList<QubitModel> Models,
    double ErrorBudget = FrameBudget.DefaultFrame,
    int Qpus = 1);
