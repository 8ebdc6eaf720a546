namespace QuantumRayTracing.Estimation;

/// <summary>
/// The seam for mean-estimation circuits, beside <see cref="Engines.IGroverEngine"/> for search: batches of
/// coin flips, QSS runs and single-ancilla phase-estimation shots in, outcomes out, in request order. Estimators above it are shared by every engine.
/// </summary>
public interface ICoinEngine : IDisposable
{
    string Name { get; }

    /// <summary>The head count of each request.</summary>
    IReadOnlyList<int> FlipCoins(IReadOnlyList<CoinRequest> requests);

    /// <summary>The counter readouts of each request, <see cref="QssRequest.Shots"/> of them.</summary>
    IReadOnlyList<int[]> ReadCounters(IReadOnlyList<QssRequest> requests);

    /// <summary>The shots whose ancilla read 0, of each request.</summary>
    IReadOnlyList<int> CountAncillaZeros(IReadOnlyList<AncillaPhaseRequest> requests);
}
