namespace QuantumRayTracing.Scenes;

/// <summary>
/// A triangle with corners <see cref="A"/>, <see cref="B"/> and <see cref="C"/> on the scene's grid, of non-zero area.
/// Seen from either side; the order of the corners does not matter to its test.
/// </summary>
public sealed record Triangle(int Id, Vec3 A, Vec3 B, Vec3 C, Material Material) : Primitive(Id, Material)
{
    /// <summary>Corner 0, 1 or 2.</summary>
    public Vec3 this[int corner] => corner switch
    {
        0 => A,
        1 => B,
        2 => C,
        _ => throw new ArgumentOutOfRangeException(nameof(corner), corner, "a triangle has corners 0, 1 and 2"),
    };

    public override (Vec3 Min, Vec3 Max) Bounds => (
        new Vec3(Math.Min(A.X, Math.Min(B.X, C.X)), Math.Min(A.Y, Math.Min(B.Y, C.Y)), Math.Min(A.Z, Math.Min(B.Z, C.Z))),
        new Vec3(Math.Max(A.X, Math.Max(B.X, C.X)), Math.Max(A.Y, Math.Max(B.Y, C.Y)), Math.Max(A.Z, Math.Max(B.Z, C.Z))));

    /// <summary>(B − A) × (C − A), normalised.</summary>
    public override Vec3 Normal => (B - A).Cross(C - A).Normalized();

    /// <summary>In the triangle's plane (to a relative 1e-12 of its size) and inside or on its edges.</summary>
    public override bool Contains(Vec3 point)
    {
        var normal = (B - A).Cross(C - A);
        var size = Math.Max((B - A).Length, Math.Max((C - B).Length, (A - C).Length));
        if (Math.Abs(normal.Dot(point - A)) > 1e-12 * normal.Length * size) return false;
        var (u, v, w) = ((B - A).Cross(point - A).Dot(normal), (C - B).Cross(point - B).Dot(normal), (A - C).Cross(point - C).Dot(normal));
        return u >= 0 && v >= 0 && w >= 0;
    }
}
