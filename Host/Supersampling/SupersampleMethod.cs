using QuantumRayTracing.Estimation;
using System.Runtime.Serialization;

namespace QuantumRayTracing.Supersampling;

/// <summary>How `supersample` estimates each pixel's mean.</summary>
public enum SupersampleMethod
{
    /// <summary>Monte Carlo: one flip of the Monte Carlo coin per query.</summary>
    Mc,

    /// <summary>Quantum supersampling: bit planes through the lookup table, or one run on the continuous values.</summary>
    Qss,

    /// <summary>QCoin, Algorithm 1 of paper 003.</summary>
    QCoin,

    /// <summary>Maximum-likelihood amplitude estimation with the exponential schedule.</summary>
    Mlae,

    /// <summary>
    /// MLAE whose likelihood includes a depolarizing decay per Grover operator, estimated jointly with the mean
    /// (<see cref="NoiseAwareMaximumLikelihoodEstimator"/>): <see cref="Mlae"/>'s shallow levels first, then the rest of the
    /// budget where the decay they show leaves the most information per query.
    /// </summary>
    [EnumMember(Value = "mlae-noise")]
    MlaeNoise,

    /// <summary>Iterative QAE with the fix against its bias (<see cref="IterativeAmplitudeEstimator"/>).</summary>
    Iqae,

    /// <summary>Faster amplitude estimation, two stages (<see cref="FasterAmplitudeEstimator"/>).</summary>
    Fae,

    /// <summary>Bayesian amplitude estimation on a grid posterior (<see cref="BayesianAmplitudeEstimator"/>).</summary>
    Bae,

    /// <summary>QSS with single-ancilla Bayesian phase estimation in place of its counter (<see cref="BayesianPhaseEstimator"/>).</summary>
    [EnumMember(Value = "qss-bayes")]
    QssBayes,

    /// <summary>Power-law amplitude estimation (<see cref="PowerLawAmplitudeEstimator"/>).</summary>
    [EnumMember(Value = "powerlaw")]
    PowerLaw,
}
