namespace QuantumRayTracing.Output;

/// <summary>How data values are spread along a plot axis.</summary>
public enum AxisScale
{
    /// <summary>Equal differences take equal distances.</summary>
    Linear,

    /// <summary>Equal ratios take equal distances; values that are not positive cannot be shown.</summary>
    Log10,
}
