namespace QuantumRayTracing.Estimation;

/// <summary>
/// Estimates the mean of each item's values F(i) ∈ [0, 1] (a pixel's subpixels, a shading point's light samples) with a fixed number of queries per item,
/// advancing every item in lock step so each round is one engine batch.
/// </summary>
public interface IMeanEstimator
{
    /// <summary>Name as chosen on the command line, with its parameters.</summary>
    string Name { get; }

    /// <summary>Queries spent per item (docs/conventions.md).</summary>
    long Queries { get; }

    /// <summary>One estimate in [0, 1] per item, in order.</summary>
    IReadOnlyList<double> Estimate(IReadOnlyList<double[]> values, ICoinEngine engine);
}
