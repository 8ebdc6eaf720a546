namespace QuantumRayTracing.Estimation;

/// <summary>
/// The QCoin paper's hardware setting (sec. 6): every coin is one qubit rotated straight to its head amplitude, which the
/// host computes from the subpixel values, instead of the subpixel register and the shader oracle. A mean coin becomes
/// √(1 − f)|0⟩ + √f|1⟩ with f = (1/N) Σ a_i²; QCoin's shifted coin √(1 − (f − E)²)|0⟩ + (f − E)|1⟩. The head
/// probabilities are those of the full coins; only the circuits, and so their noise, differ. QSS runs likewise on the
/// one coin qubit under its counter (the paper's device QSS, fig. 9 top).
/// </summary>
public sealed class DirectCoinEngine(ICoinEngine inner) : ICoinEngine
{
    public string Name => $"{inner.Name}, direct single-qubit coins";

    public IReadOnlyList<int> FlipCoins(IReadOnlyList<CoinRequest> requests) =>
        inner.FlipCoins(requests.Select(r => r.Kind switch
        {
            CoinKind.Shifted => r with { Kind = CoinKind.Direct, Amplitudes = [CoinProbability.HeadAmplitude(CoinKind.Shifted, r.Amplitudes)] },
            _ => r with { Kind = CoinKind.Direct },
        }).ToArray());

    public IReadOnlyList<int[]> ReadCounters(IReadOnlyList<QssRequest> requests) =>
        inner.ReadCounters(requests.Select(r => r with { Coin = CoinKind.Direct, Amplitudes = [CoinProbability.HeadAmplitude(CoinKind.Mean, r.Amplitudes)] }).ToArray());

    /// <summary>The ancilla's circuit needs the coin register under control; it has no single-qubit form here.</summary>
    public IReadOnlyList<int> CountAncillaZeros(IReadOnlyList<AncillaPhaseRequest> requests) =>
        requests.Count == 0 ? [] : throw new ArgumentException("single-ancilla phase estimation runs on the mean coin, not on the direct single-qubit coin");

    public void Dispose() => inner.Dispose();
}
