using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// What the estimated circuits are built for: one ray's oracle input (its table, window and the
/// oracle's construction) and the Grover iterations r of a search run. Circuits with other parameters
/// (supersampling's subpixel and counter bits) add them here.
/// </summary>
/// <param name="Oracle">The ray's oracle input.</param>
/// <param name="Iterations">r of the QSearch run row.</param>
/// <param name="Label">Where the ray came from, for tables (e.g. "pixel (40, 7)").</param>
public sealed record EstimateSubject(OracleInput Oracle, int Iterations, string Label);
