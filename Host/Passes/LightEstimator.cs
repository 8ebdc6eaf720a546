namespace QuantumRayTracing.Passes;

/// <summary>How `render` estimates each shading point's area light from its fixed set of samples (docs/rendering.md).</summary>
public enum LightEstimator
{
    /// <summary>Monte Carlo: samples drawn uniformly from the set, one query each; without --light-queries, every sample traced (the default).</summary>
    Mc,

    /// <summary>QCoin, Algorithm 1 of the QCoin paper.</summary>
    QCoin,

    /// <summary>Maximum-likelihood amplitude estimation with the exponential schedule.</summary>
    Mlae,

    /// <summary>Iterative QAE with the fix against its bias.</summary>
    Iqae,

    /// <summary>Bayesian amplitude estimation on a grid posterior.</summary>
    Bae,
}
