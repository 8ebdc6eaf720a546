using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Estimation;

/// <summary>
/// Classical Monte Carlo on an item's values themselves: <see cref="Queries"/> indices drawn uniformly, with replacement,
/// from the item's set, estimate = the mean of the values drawn. One query per draw (one sample evaluated). The stronger
/// classical baseline where each value is known exactly once drawn (a light sample's weight times its visibility), against
/// <see cref="MonteCarloEstimator"/>'s coin, which only flips with probability F(i).
/// </summary>
public sealed class SampleMeanEstimator : IMeanEstimator
{
    private readonly SeededRandom _random;

    public SampleMeanEstimator(long queries, SeededRandom random)
    {
        if (queries < 1 || queries > int.MaxValue) throw new ArgumentOutOfRangeException(nameof(queries), queries, "Monte Carlo needs at least one query");
        Queries = queries;
        _random = random;
    }

    public string Name => "mc";

    public long Queries { get; }

    /// <summary>Draws from this estimator's own stream, item by item in order; the engine is not asked.</summary>
    public IReadOnlyList<double> Estimate(IReadOnlyList<double[]> values, ICoinEngine engine)
    {
        var estimates = new double[values.Count];
        for (var j = 0; j < values.Count; j++)
        {
            CoinValues.Check(values[j]);
            var sum = 0.0;
            for (var q = 0; q < Queries; q++) sum += values[j][_random.NextInt(values[j].Length)];
            estimates[j] = sum / Queries;
        }
        return estimates;
    }
}
