namespace QuantumRayTracing.Estimation;

/// <summary>The queries one item's estimate spent: ours (a flip 1, a Grover operator 2) and the AE papers' (Grover operators only).</summary>
/// <param name="Queries">Σ flips · (1 + 2m), docs/conventions.md.</param>
/// <param name="GroverOperators">Σ flips · m: the count IQAE, FAE and BAE report as oracle calls.</param>
public readonly record struct QueryTally(long Queries, long GroverOperators);
