using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Estimation;

/// <summary>
/// Samples the supersampling circuits' exact outcome distributions (<see cref="CoinProbability"/>) with a
/// seeded generator, in request order: the same seed and requests give the same outcomes. Under noise each
/// flip and readout is drawn from the global depolarizing approximation (<see cref="SupersamplingNoise"/>); under a
/// device model, which this engine runs on the single-qubit coins only, from <see cref="DeviceNoise"/>.
/// </summary>
public sealed class AnalyticCoinEngine(SeededRandom random, NoiseModel? noise = null, DepolarizingApproximation? approximation = null, DeviceNoiseModel? device = null) : ICoinEngine
{
    /// <summary>Why a device model cannot run a request: its gates are counted by arity for the single-qubit coins only.</summary>
    public const string DeviceNeedsDirectCoins = "the device noise model runs the single-qubit (direct) coins and QSS on them, the QCoin paper's device circuits";

    public string Name => "analytic";

    /// <summary>The noise outcomes are sampled under; the ideal model takes the exact path, draw for draw.</summary>
    public NoiseModel Noise { get; } = noise is { QubitLoss: > 0 }
        ? throw new ArgumentException("the analytic engine does not model qubit loss", nameof(noise))
        : noise ?? NoiseModel.None;

    public DepolarizingApproximation Approximation { get; } = approximation ?? DepolarizingApproximation.Default;

    /// <summary>The device model outcomes are sampled under, or null; it replaces <see cref="Noise"/>, which must then be ideal.</summary>
    public DeviceNoiseModel? Device { get; } = DeviceNoiseModel.Alone(device, noise);

    public IReadOnlyList<int> FlipCoins(IReadOnlyList<CoinRequest> requests)
    {
        var heads = new int[requests.Count];
        for (var k = 0; k < requests.Count; k++)
        {
            var request = requests[k];
            var p = Device is not null
                ? request.Kind == CoinKind.Direct
                    ? DeviceNoise.DirectCoinHeadProbability(Device, CoinProbability.HeadAmplitude(request.Kind, request.Amplitudes), request.Iterations)
                    : throw new ArgumentException(DeviceNeedsDirectCoins)
                : Noise.IsNoiseless
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
            var distribution = QssDistribution(request);
            readouts[k] = new int[request.Shots];
            for (var shot = 0; shot < request.Shots; shot++) readouts[k][shot] = Categorical(distribution);
        }
        return readouts;
    }

    /// <summary>Exact Bernoulli draws at P(0) = cos²(kθ) (<see cref="CoinProbability.AncillaZero"/>); noiseless only.</summary>
    public IReadOnlyList<int> CountAncillaZeros(IReadOnlyList<AncillaPhaseRequest> requests)
    {
        if (requests.Count > 0 && (Device is not null || !Noise.IsNoiseless))
            throw new ArgumentException("single-ancilla phase estimation runs noiseless only on the analytic engine");
        var zeros = new int[requests.Count];
        for (var k = 0; k < requests.Count; k++)
            zeros[k] = Binomial(requests[k].Shots, CoinProbability.AncillaZero(CoinProbability.HeadAmplitude(CoinKind.Mean, requests[k].Amplitudes), requests[k].Power));
        return zeros;
    }

    private double[] QssDistribution(QssRequest request)
    {
        var amplitude = CoinProbability.HeadAmplitude(CoinKind.Mean, request.Amplitudes);
        if (request.Coin == CoinKind.Direct)
        {
            if (Device is not null) return DeviceNoise.DirectQssReadout(Device, amplitude, request.CounterBits, Approximation);
            if (!Noise.IsNoiseless) throw new ArgumentException("QSS on the single-qubit coin runs noiseless or under a device model");
        }
        else if (Device is not null) throw new ArgumentException(DeviceNeedsDirectCoins);
        return Noise.IsNoiseless
            ? CoinProbability.QssReadout(amplitude * amplitude, request.CounterBits)
            : SupersamplingNoise.QssReadout(request.Amplitudes, request.CounterBits, Noise, Approximation);
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
