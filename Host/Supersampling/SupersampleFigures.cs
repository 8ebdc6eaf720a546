using QuantumRayTracing.Estimation;
using QuantumRayTracing.Metrics;

namespace QuantumRayTracing.Supersampling;

/// <summary>
/// Everything `supersample` prints about a run, in one record its text and its --json file are both written from:
/// the input and its size, the QSS lookup table used (if any), the estimator and its queries (docs/conventions.md),
/// the error against the exact average, the confidence of bit-plane QSS, the wall times and the files written.
/// </summary>
public sealed record SupersampleFigures(
    string Input,
    int InputWidth,
    int InputHeight,
    int Subpixels,
    int OutputWidth,
    int OutputHeight,
    TimeSpan? InputRenderTime,
    int? LookupTableReadouts,
    string Estimator,
    long QueriesPerChannel,
    int ChannelsEstimated,
    long TotalQueries,
    SupersampleError Error,
    double? MeanConfidence,
    double? LowestConfidence,
    TimeSpan WallTime,
    IReadOnlyList<string> Written);
