namespace QuantumRayTracing.Estimation;

/// <summary>
/// Flip a coin <see cref="Flips"/> times, each flip prepared afresh and amplified by
/// <see cref="Iterations"/> Grover operators; the engine returns the number of heads.
/// </summary>
/// <param name="Kind">Which coin.</param>
/// <param name="Amplitudes">
/// One amplitude a_i ∈ [−1, 1] per subpixel (at least one). The direct coin prepares the head amplitude √((1/N) Σ a_i²) on
/// its one qubit: √F(i) give the mean f, and a single amplitude a gives |a| (a shifted mean f − E, as QCoin's steps need).
/// </param>
/// <param name="Iterations">Grover operators per flip, m ≥ 0.</param>
/// <param name="Flips">Flips, ≥ 0.</param>
public sealed record CoinRequest(CoinKind Kind, double[] Amplitudes, int Iterations, int Flips)
{
    /// <summary>docs/conventions.md: the preparation is one query, each Grover operator two (oracle and inverse).</summary>
    public long Queries => (long)Flips * (1 + 2L * Iterations);
}
