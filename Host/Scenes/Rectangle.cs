namespace QuantumRayTracing.Scenes;

/// <summary>
/// An axis-aligned rectangle: min and max corners on the scene's grid, equal on exactly one axis
/// (<see cref="FlatAxis"/>, the axis of its plane's normal).
/// </summary>
public sealed record Rectangle(int Id, Vec3 Min, Vec3 Max, int FlatAxis, Material Material) : Primitive(Id, Material)
{
    /// <summary>The coordinate of the rectangle's plane along <see cref="FlatAxis"/>.</summary>
    public double PlaneOffset => Min[FlatAxis];

    public override (Vec3 Min, Vec3 Max) Bounds => (Min, Max);

    /// <summary>The unit vector along <see cref="FlatAxis"/>.</summary>
    public override Vec3 Normal => FlatAxis switch
    {
        0 => new Vec3(1, 0, 0),
        1 => new Vec3(0, 1, 0),
        _ => new Vec3(0, 0, 1),
    };

    public override bool Contains(Vec3 point) =>
        Enumerable.Range(0, 3).All(axis => Min[axis] <= point[axis] && point[axis] <= Max[axis]);
}
