namespace QuantumRayTracing.Estimation;

/// <summary>
/// The baseline: <see cref="Queries"/> flips of the Monte Carlo coin Q_{√F,0} (one random subpixel, a head
/// with probability F(i)), estimate = heads / flips. One query per flip.
/// </summary>
public sealed class MonteCarloEstimator : IMeanEstimator
{
    public MonteCarloEstimator(long queries)
    {
        if (queries < 1 || queries > int.MaxValue) throw new ArgumentOutOfRangeException(nameof(queries), queries, "Monte Carlo needs at least one query");
        Queries = queries;
    }

    public string Name => "mc";

    public long Queries { get; }

    public IReadOnlyList<double> Estimate(IReadOnlyList<double[]> values, ICoinEngine engine)
    {
        foreach (var v in values) CoinValues.Check(v);
        var heads = engine.FlipCoins(values.Select(v => new CoinRequest(CoinKind.Mean, CoinValues.MeanCoin(v), 0, (int)Queries)).ToArray());
        return heads.Select(h => (double)h / Queries).ToArray();
    }
}
