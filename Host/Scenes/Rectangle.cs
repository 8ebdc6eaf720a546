namespace QuantumRayTracing.Scenes;

/// <summary>
/// An axis-aligned rectangle, the only primitive: min and max corners on the scene's grid, equal on
/// exactly one axis (<see cref="FlatAxis"/>, the axis of its plane's normal). <see cref="Id"/> is its
/// index in the scene and the tie-breaker of equal depths.
/// </summary>
public sealed record Rectangle(int Id, Vec3 Min, Vec3 Max, int FlatAxis, Material Material)
{
    /// <summary>The coordinate of the rectangle's plane along <see cref="FlatAxis"/>.</summary>
    public double PlaneOffset => Min[FlatAxis];
}
