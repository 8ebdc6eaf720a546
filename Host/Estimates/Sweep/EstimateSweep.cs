using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// The subjects of the resource sweeps: for N primitives on a c-bit grid, the <see cref="SweepScene"/>
/// and its worst-case camera ray (<see cref="EstimateRay.WorstCase"/>) among the rays of a
/// <see cref="ImageSize"/>-pixel square image, chosen under the default construction and shared by
/// every construction, so that before and after are the same ray.
/// </summary>
public static class EstimateSweep
{
    public const int ImageSize = 16;

    public static readonly IReadOnlyList<int> Primitives = [4, 8, 16, 32, 64, 128, 256, 512];

    public static readonly IReadOnlyList<int> CoordinateBits = [2, 3, 4, 5, 6, 7, 8];

    /// <summary>The paper's 16 x 16 x 16 world.</summary>
    public const int DefaultCoordinateBits = 4;

    /// <summary>The paper's default scene size.</summary>
    public const int DefaultPrimitives = 64;

    public static EstimateSubject Subject(int primitives, int coordinateBits)
    {
        var scene = SceneLoader.Parse(SweepScene.Build(primitives, coordinateBits).ToJson(), $"sweep-{primitives}-{coordinateBits}.json");
        var (input, label) = EstimateRay.WorstCase(scene, new SceneGeometry(scene), ImageSize, ImageSize, OracleConstruction.Default);
        return new EstimateSubject(input, QSearchSchedule.CeilSqrt(primitives), label);
    }

    public static EstimateSubject With(this EstimateSubject subject, OracleConstruction construction) =>
        subject with { Oracle = subject.Oracle with { Construction = construction } };
}
