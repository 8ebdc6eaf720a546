using QuantumRayTracing.Estimation;
using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Passes;

/// <summary>
/// Area light estimated as a mean over each shading point's fixed set of samples, read by <paramref name="Estimator"/>
/// with <paramref name="Queries"/> queries per point and area light (docs/rendering.md, *Quantum light estimation*).
/// </summary>
/// <param name="Estimator">The estimator: Monte Carlo draws from the set, the others read the set's coin.</param>
/// <param name="Queries">Q per point and light, in <see cref="MinQueries"/>..<see cref="MaxQueries"/>; the adaptive estimators (iqae, bae) may stop below it.</param>
public sealed record LightEstimation(LightEstimator Estimator, int Queries)
{
    /// <summary>The fewest queries every estimator runs on: QCoin's first step and one amplified flip.</summary>
    public const int MinQueries = 4;

    /// <summary>The most queries per point and light.</summary>
    public const int MaxQueries = 1 << 16;

    /// <summary>Q when only --light-estimator is given.</summary>
    public const int DefaultQueries = 64;

    public string Name => Estimator.ToString().ToLowerInvariant();

    /// <summary>The estimator at Q queries with its default parameters; Monte Carlo draws from <paramref name="random"/>.</summary>
    public IMeanEstimator CreateEstimator(SeededRandom random)
    {
        if (Queries is < MinQueries or > MaxQueries) throw new ArgumentOutOfRangeException(nameof(Queries), Queries, $"light queries must lie in {MinQueries}..{MaxQueries}");
        return Estimator switch
        {
            LightEstimator.Mc => new SampleMeanEstimator(Queries, random),
            LightEstimator.QCoin => new QCoinEstimator(Queries, QCoinEstimator.DefaultSteps(Queries)),
            LightEstimator.Mlae => new MaximumLikelihoodEstimator(Queries, MaximumLikelihoodEstimator.DefaultLevels(Queries)),
            LightEstimator.Iqae => new IterativeAmplitudeEstimator(Queries),
            LightEstimator.Bae => new BayesianAmplitudeEstimator(Queries),
            _ => throw new ArgumentOutOfRangeException(nameof(Estimator), Estimator, null),
        };
    }

    /// <summary>Whether <paramref name="samples"/> fills a register of whole qubits: M = 2^k.</summary>
    public static bool IsRegisterSize(int samples) => samples > 0 && (samples & (samples - 1)) == 0;
}
