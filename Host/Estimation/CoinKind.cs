namespace QuantumRayTracing.Estimation;

/// <summary>Which coin a flip uses (Q# <c>PrepareMeanCoin</c>, <c>PrepareShiftedCoin</c> or <c>CountDirectCoinHeads</c>).</summary>
public enum CoinKind
{
    /// <summary>Head = coin qubit |1⟩; probability (1/N) Σ a_i². With a_i = √F(i): the Monte Carlo coin.</summary>
    Mean,

    /// <summary>QCoin's Q_{F,E}: head = coin |1⟩ with subpixel register 0; amplitude (1/N) Σ a_i, i.e. f − E.</summary>
    Shifted,

    /// <summary>
    /// The QCoin paper's hardware coin (sec. 6): one qubit prepared as √(1 − f)|0⟩ + √f|1⟩ by one Ry, f = (1/N) Σ a_i²
    /// computed by the host; head = |1⟩, the same probability as <see cref="Mean"/> on far fewer gates.
    /// </summary>
    Direct,
}
