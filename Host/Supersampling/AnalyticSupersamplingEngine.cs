using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Supersampling;

/// <summary>
/// Samples the supersampling circuits' exact outcome distributions (<see cref="CoinProbability"/>) with a
/// seeded generator, in request order: the same seed and requests give the same outcomes. Under noise each
/// flip and readout is drawn from the global depolarizing approximation (<see cref="SupersamplingNoise"/>).
/// </summary>
public sealed class AnalyticSupersamplingEngine(SeededRandom random, NoiseModel? noise = null, DepolarizingApproximation? approximation = null) : ISupersamplingEngine
{
    public string Name => "analytic";

    /// <summary>The noise outcomes are sampled under; the ideal model takes the exact path, draw for draw.</summary>
    public NoiseModel Noise { get; } = noise is { QubitLoss: > 0 }
        ? throw new ArgumentException("the analytic engine does not model qubit loss", nameof(noise))
        : noise ?? NoiseModel.None;

    public DepolarizingApproximation Approximation { get; } = approximation ?? DepolarizingApproximation.Default;

    public IReadOnlyList<int> FlipCoins(IReadOnlyList<CoinRequest> requests)
    {
        var heads = new int[requests.Count];
        for (var k = 0; k < requests.Count; k++)
        {
            var request = requests[k];
            var p = Noise.IsNoiseless
                ? CoinProbability.Head(CoinProbability.HeadAmplitude(request.Kind, request.Amplitudes), request.Iterations)
                : SupersamplingNoise.CoinHeadProbability(request.Kind, request.Amplitudes, request.Iterations, Noise, Approximation);
            heads[k] = Binomial(request.Flips, p);
        }
        return heads;
    }

    public IReadOnlyList<int[]> ReadCounters(IReadOnlyList<QssRequest> requests)
    {
        var readouts = new int[requests.Count][];
        for (var k = 0; k < requests.Count; k++)
        {
            var request = requests[k];
            var distribution = Noise.IsNoiseless
                ? CoinProbability.QssReadout(CoinProbability.HeadAmplitude(CoinKind.Mean, request.Amplitudes) is var s ? s * s : 0, request.CounterBits)
                : SupersamplingNoise.QssReadout(request.Amplitudes, request.CounterBits, Noise, Approximation);
            readouts[k] = new int[request.Shots];
            for (var shot = 0; shot < request.Shots; shot++) readouts[k][shot] = Categorical(distribution);
        }
        return readouts;
    }

    private int Binomial(int trials, double p)
    {
        // p = 0 and p = 1 are exact: no draw can turn them into anything else.
        if (p <= 0) return 0;
        if (p >= 1) return trials;
        var count = 0;
        for (var i = 0; i < trials; i++)
            if (random.NextDouble() < p) count++;
        return count;
    }

    private int Categorical(double[] distribution)
    {
        var u = random.NextDouble();
        for (var y = 0; y < distribution.Length; y++)
        {
            u -= distribution[y];
            if (u < 0) return y;
        }
        // Rounding left u a hair above the total: the last outcome with non-zero probability.
        for (var y = distribution.Length - 1; y >= 0; y--)
            if (distribution[y] > 0) return y;
        return 0;
    }

    public void Dispose() { }
}
