namespace QuantumRayTracing.Estimation;

/// <summary>What one level of maximum-likelihood amplitude estimation saw: heads in its flips after m Grover operators each.</summary>
/// <param name="Iterations">m, Grover operators per flip.</param>
/// <param name="Heads">Heads seen, 0 ≤ heads ≤ flips.</param>
/// <param name="Flips">Flips made.</param>
public readonly record struct MlaeLevel(int Iterations, int Heads, int Flips);
