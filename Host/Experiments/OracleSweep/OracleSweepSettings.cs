using QuantumRayTracing.Estimates;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `estimate oracle-sweep` estimates: the oracle at each of <paramref name="Primitives"/> (default grid) and each of
/// <paramref name="Bits"/> (default N), each change of the construction alone at <paramref name="Ablation"/>, on
/// <paramref name="Models"/>, with the extracted circuits' gates and depth when <paramref name="WithCircuits"/>, on
/// <paramref name="Workers"/> bridges.
/// </summary>
public sealed record OracleSweepSettings(IReadOnlyList<int> Primitives, IReadOnlyList<int> Bits, IReadOnlyList<int> Ablation, IReadOnlyList<QubitModel> Models, bool WithCircuits, int Workers);
