namespace QuantumRayTracing.Supersampling;

/// <summary>Which coin a flip uses (Q# <c>PrepareMeanCoin</c> or <c>PrepareShiftedCoin</c>).</summary>
public enum CoinKind
{
    /// <summary>Head = coin qubit |1⟩; probability (1/N) Σ a_i². With a_i = √F(i): the Monte Carlo coin.</summary>
    Mean,

    /// <summary>QCoin's Q_{F,E}: head = coin |1⟩ with subpixel register 0; amplitude (1/N) Σ a_i, i.e. f − E.</summary>
    Shifted,
}
