using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// What the estimated circuits are built for: one ray's oracle input (its table, window and the
/// oracle's construction), the Grover iterations r of a search run, the supersampling circuits'
/// subpixel count and QSS counter bits, and the rays of a pooled query.
/// </summary>
/// <param name="Oracle">The ray's oracle input.</param>
/// <param name="Iterations">r of the QSearch run row.</param>
/// <param name="Label">Where the ray came from, for tables (e.g. "pixel (40, 7)").</param>
/// <param name="Subpixels">Subpixels of the QSS readout and the QCoin step (the thesis's 4x4 = 16 by default).</param>
/// <param name="CounterBits">QSS counter register width.</param>
/// <param name="Pool">The rays of a pooled query's pool (<see cref="EstimatedCircuits.Pooled"/>), or null.</param>
public sealed record EstimateSubject(OracleInput Oracle, int Iterations, string Label, int Subpixels = 16, int CounterBits = 4, IReadOnlyList<OracleInput>? Pool = null)
{
    /// <summary>
    /// The subpixel values the supersampling circuits are estimated for: half lit, alternating 0 and 1.
    /// Gate counts do not depend on the values, only on their number (each becomes one rotation).
    /// </summary>
    public string CoinValues => "[" + string.Join(", ", Enumerable.Range(0, Subpixels).Select(k => k % 2 == 0 ? "0.0" : "1.0")) + "]";
}
