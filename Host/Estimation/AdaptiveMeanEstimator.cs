namespace QuantumRayTracing.Estimation;

/// <summary>
/// A mean estimator that runs one <see cref="IAdaptiveCoinSearch"/> per item (<see cref="AdaptiveFlips"/>) within a budget
/// of <see cref="Queries"/> per item; an item may stop below it, and <see cref="EstimateCounted"/> says what each spent.
/// </summary>
public abstract class AdaptiveMeanEstimator : IMeanEstimator
{
    protected AdaptiveMeanEstimator(long queries)
    {
        if (queries < 1 || queries > int.MaxValue) throw new ArgumentOutOfRangeException(nameof(queries), queries, "an estimate needs at least one query");
        Queries = queries;
    }

    public abstract string Name { get; }

    /// <summary>The budget per item: no item spends more.</summary>
    public long Queries { get; }

    /// <summary>The mean coin's amplitudes are scaled by this (1: the plain mean coin).</summary>
    protected virtual double AmplitudeScale => 1;

    /// <summary>A fresh search for one item.</summary>
    protected abstract IAdaptiveCoinSearch CreateSearch();

    /// <summary>How a round's requests are measured: by default flips of the coin, heads counted.</summary>
    protected virtual IReadOnlyList<int> Measure(ICoinEngine engine, IReadOnlyList<CoinRequest> requests) => engine.FlipCoins(requests);

    public IReadOnlyList<double> Estimate(IReadOnlyList<double[]> values, ICoinEngine engine) => EstimateCounted(values, engine).Estimates;

    /// <summary>The estimates and the queries each item spent.</summary>
    public (double[] Estimates, QueryTally[] Spent) EstimateCounted(IReadOnlyList<double[]> values, ICoinEngine engine) =>
        AdaptiveFlips.Run(values, engine, CreateSearch, Queries, AmplitudeScale, Measure);
}
