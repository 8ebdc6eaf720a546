using QuantumRayTracing.Estimation;
namespace QuantumRayTracing.Supersampling;

/// <summary>
/// What a <see cref="SupersampleRun"/> models, known once its input is read and before the estimates are paid for:
/// the input and how it was made, the QSS lookup table (bit planes only) and the estimator.
/// </summary>
/// <param name="InputName">The image file's name, or the scene's.</param>
/// <param name="Input">The input, s x s subpixels per output pixel.</param>
/// <param name="RenderTime">How long the classical render of a scene took; null for an image file.</param>
/// <param name="Table">The lookup table bit-plane QSS reads; null for the other methods.</param>
/// <param name="TablePath">Where the table is kept between runs.</param>
/// <param name="TableWasCached">The table was read from <paramref name="TablePath"/>, not built (and written there).</param>
/// <param name="Estimator">The estimator, with its queries per pixel and channel.</param>
public sealed record SupersamplePlan(
    string InputName,
    SubpixelImage Input,
    TimeSpan? RenderTime,
    QssLookupTable? Table,
    string? TablePath,
    bool TableWasCached,
    IMeanEstimator Estimator);
