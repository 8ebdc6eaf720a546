namespace QuantumRayTracing.Supersampling;

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

    public IReadOnlyList<double> Estimate(IReadOnlyList<double[]> values, ISupersamplingEngine engine)
    {
        foreach (var v in values) SubpixelValues.Check(v);
        var heads = engine.FlipCoins(values.Select(v => new CoinRequest(CoinKind.Mean, SubpixelValues.MeanCoin(v), 0, (int)Queries)).ToArray());
        return heads.Select(h => (double)h / Queries).ToArray();
    }
}
