using QuantumRayTracing.Estimation;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Supersampling;

/// <summary>
/// A supersampled image: the estimate of each pixel and channel (index 3·pixel + channel), the 8-bit image made
/// from them, and for bit-plane QSS each pixel's confidence and the confidence map (grey, white = sure).
/// </summary>
public sealed record SupersampleResult(
    double[] Estimates,
    RgbImage Image,
    double[]? Confidence,
    RgbImage? ConfidenceMap,
    long QueriesPerChannel,
    int ChannelsEstimated,
    string Estimator);
