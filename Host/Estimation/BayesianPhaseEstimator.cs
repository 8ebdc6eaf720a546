namespace QuantumRayTracing.Estimation;

/// <summary>
/// QSS with Bayesian phase estimation in place of its counter (after Lu and Lin, Quantum Information Processing 22, 2023):
/// QSS's t-qubit counter and inverse QFT become one ancilla that controls k Grover operators on the mean coin and is read
/// in the X basis (<see cref="AncillaPhaseRequest"/>: 0 with probability cos²(kθ)); k is chosen adaptively on
/// <see cref="BayesianAmplitudeEstimator"/>'s grid posterior (most expected variance reduction of f per query), and the
/// estimate is the posterior median of f. A shot at power k costs 1 + 2k queries, the count of a QSS run whose
/// counter controls k Grover operators in all.
/// </summary>
public sealed class BayesianPhaseEstimator : AdaptiveMeanEstimator
{
    private readonly PosteriorFringe _fringe;

    public BayesianPhaseEstimator(long queries) : this(queries, PosteriorFringe.AncillaPhase) { }

    /// <summary>With another likelihood than the circuit's: for the negative control that shows a wrong fringe fails.</summary>
    internal BayesianPhaseEstimator(long queries, PosteriorFringe fringe) : base(queries) => _fringe = fringe;

    public override string Name => "qss-bayes";

    protected override IAdaptiveCoinSearch CreateSearch() => new GridPosteriorSearch(_fringe);

    protected override IReadOnlyList<int> Measure(ICoinEngine engine, IReadOnlyList<CoinRequest> requests) =>
        engine.CountAncillaZeros(requests.Select(r => new AncillaPhaseRequest(r.Amplitudes, r.Iterations, r.Flips)).ToArray());
}
