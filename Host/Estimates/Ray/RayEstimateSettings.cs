using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// What `estimate` prices for one ray: the camera ray through <paramref name="Pixel"/> of a width x height image
/// (null: the worst case, <see cref="EstimateRay.WorstCase"/>), the QSearch run's iterations (null: ceil(sqrt N)),
/// the supersampling rows' subpixels and counter bits, the oracle construction, the qubit models, whether each
/// circuit is simulated once for its gates by kind and depth, the local bridges estimating in parallel, and the rays of a
/// pooled query's pool (null: no pooled circuits).
/// </summary>
public sealed record RayEstimateSettings(Scene Scene, int Width, int Height, (int X, int Y)? Pixel, int? Iterations, int Subpixels, int CounterBits,
    OracleConstruction Construction, IReadOnlyList<QubitModel> Models, bool WithCircuits, int Workers, int? PooledRays = null);
