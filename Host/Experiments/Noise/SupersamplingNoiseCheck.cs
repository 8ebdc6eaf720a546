using QuantumRayTracing.Bridge;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

using QuantumRayTracing.Noise;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// One circuit of the supersampling model check: a coin of <see cref="Kind"/> flipped after <see cref="Iterations"/>
/// Grover operators, or (Kind null) a QSS run with <see cref="CounterBits"/> counter qubits. What is counted: a head,
/// or a QSS readout at one of the ideal distribution's two most likely values (y and 2^t − y, the two
/// eigenphases), whose share noise pulls towards 2/2^t.
/// </summary>
public sealed record SupersamplingCheckCase(CoinKind? Kind, double[] Amplitudes, int Iterations = 0, int CounterBits = 0)
{
    public static SupersamplingCheckCase Coin(CoinKind kind, double[] amplitudes, int iterations) => new(kind, amplitudes, iterations);

    public static SupersamplingCheckCase Qss(double[] amplitudes, int counterBits) => new(null, amplitudes, CounterBits: counterBits);

    public bool IsQss => Kind is null;

    /// <summary>"mean", "shifted", "direct" or "QSS", with N: the circuit shape a harmful share is fitted to.</summary>
    public string Shape => (Kind is { } kind ? kind.ToString().ToLowerInvariant() + " coin" : "QSS") + $", N = {Subpixels}";

    public int Subpixels => Amplitudes.Length;

    /// <summary>The mean the coin or the QSS readout estimates: (1/N) Σ a_i² (the shifted coin: its head amplitude).</summary>
    public double HeadAmplitude => CoinProbability.HeadAmplitude(Kind ?? CoinKind.Mean, Amplitudes);

    /// <summary>Noise locations of one run (<see cref="CoinNoiseLocations"/>).</summary>
    public long Locations => Kind is { } kind ? CoinNoiseLocations.Flip(kind, Amplitudes, Iterations) : CoinNoiseLocations.Qss(Amplitudes, CounterBits);

    /// <summary>The QSS readouts counted: the ideal distribution's most likely value and its mirror 2^t − y.</summary>
    public IReadOnlySet<int> CountedReadouts
    {
        get
        {
            var ideal = SupersamplingNoise.QssReadout(Amplitudes, CounterBits, NoiseModel.None);
            var best = Array.IndexOf(ideal, ideal.Max());
            return new HashSet<int> { best, (ideal.Length - best) % ideal.Length };
        }
    }

    /// <summary>Probability of the counted outcome under <paramref name="noise"/> as the approximation predicts it.</summary>
    public double Predicted(NoiseModel noise, DepolarizingApproximation approximation)
    {
        if (Kind is { } kind) return SupersamplingNoise.CoinHeadProbability(kind, Amplitudes, Iterations, noise, approximation);
        var distribution = SupersamplingNoise.QssReadout(Amplitudes, CounterBits, noise, approximation);
        return CountedReadouts.Sum(y => distribution[y]);
    }
}

/// <summary>A case run <see cref="Shots"/> times on the noisy simulator under <see cref="Noise"/>, with <see cref="Hits"/> counted outcomes.</summary>
public sealed record SupersamplingCheckRow(SupersamplingCheckCase Case, NoiseModel Noise, int Shots, int Hits) : IModelCheckRow
{
    public double Observed => (double)Hits / Shots;

    public double Predicted(DepolarizingApproximation approximation) => Case.Predicted(Noise, approximation);

    /// <summary>The counted outcome's probability on an ideal machine.</summary>
    public double Ideal => Case.Predicted(NoiseModel.None, DepolarizingApproximation.Default);

    /// <summary>Binomial standard error of <see cref="Observed"/> at the predicted probability.</summary>
    public double StandardError(DepolarizingApproximation approximation)
    {
        var p = Math.Clamp(Predicted(approximation), 1e-9, 1 - 1e-9);
        return Math.Sqrt(p * (1 - p) / Shots);
    }
}

/// <summary>
/// Runs coin flips and QSS readouts on the noisy full-state simulator (<see cref="FullStateCoinEngine"/>) and
/// compares the share of counted outcomes with <see cref="SupersamplingNoise"/>, as <see cref="NoiseCheck"/> does for searches.
/// </summary>
public static class SupersamplingNoiseCheck
{
    /// <summary>Runs every case <paramref name="shots"/> times under each noise model: one coin batch and one QSS batch per model.</summary>
    public static IReadOnlyList<SupersamplingCheckRow> Measure(BridgePool pool, IReadOnlyList<SupersamplingCheckCase> cases, IReadOnlyList<NoiseModel> noises, int shots)
    {
        var rows = new List<SupersamplingCheckRow>();
        var coins = cases.Where(c => !c.IsQss).ToArray();
        var qss = cases.Where(c => c.IsQss).ToArray();
        foreach (var noise in noises)
        {
            using var engine = new FullStateCoinEngine(pool, ownsPool: false, noise: noise);
            var heads = engine.FlipCoins(coins.Select(c => new CoinRequest(c.Kind!.Value, c.Amplitudes, c.Iterations, shots)).ToArray());
            var readouts = engine.ReadCounters(qss.Select(c => new QssRequest(c.Amplitudes, c.CounterBits, shots)).ToArray());
            var measured = new Dictionary<SupersamplingCheckCase, int>();
            for (var k = 0; k < coins.Length; k++) measured[coins[k]] = heads[k];
            for (var k = 0; k < qss.Length; k++)
            {
                var counted = qss[k].CountedReadouts;
                measured[qss[k]] = readouts[k].Count(counted.Contains);
            }
            rows.AddRange(cases.Select(c => new SupersamplingCheckRow(c, noise, shots, measured[c])));
        }
        return rows;
    }
}
