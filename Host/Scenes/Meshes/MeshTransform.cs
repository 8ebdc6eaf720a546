namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>
/// Places a mesh: each vertex v becomes Translation + Rz(Ry(Rx(Scale · v))): scaled uniformly about the origin,
/// rotated about the x axis, then the y axis, then the z axis (degrees, right-handed: +90° about z takes x to y),
/// then translated. Rotations by whole multiples of 90° are exact (no cos 90° = 6e-17).
/// </summary>
public sealed record MeshTransform
{
    public MeshTransform(Vec3 translation, double scale, Vec3 rotationDegrees)
    {
        if (!translation.IsFinite) throw new ArgumentOutOfRangeException(nameof(translation), translation, "must be finite");
        if (!double.IsFinite(scale) || scale <= 0) throw new ArgumentOutOfRangeException(nameof(scale), scale, "must be a finite number above 0");
        if (!rotationDegrees.IsFinite) throw new ArgumentOutOfRangeException(nameof(rotationDegrees), rotationDegrees, "must be finite");
        (Translation, Scale, RotationDegrees) = (translation, scale, rotationDegrees);
    }

    public static MeshTransform Identity { get; } = new(Vec3.Zero, 1, Vec3.Zero);

    public Vec3 Translation { get; }

    public double Scale { get; }

    /// <summary>Degrees about x, y and z, applied in that order.</summary>
    public Vec3 RotationDegrees { get; }

    public Vec3 Apply(Vec3 v)
    {
        v = Scale * v;
        var (cx, sx) = CosSin(RotationDegrees.X);
        v = new Vec3(v.X, cx * v.Y - sx * v.Z, sx * v.Y + cx * v.Z);
        var (cy, sy) = CosSin(RotationDegrees.Y);
        v = new Vec3(cy * v.X + sy * v.Z, v.Y, -sy * v.X + cy * v.Z);
        var (cz, sz) = CosSin(RotationDegrees.Z);
        v = new Vec3(cz * v.X - sz * v.Y, sz * v.X + cz * v.Y, v.Z);
        return v + Translation;
    }

    public TriangleMesh Apply(TriangleMesh mesh) => mesh.MapVertices(Apply);

    private static (double Cos, double Sin) CosSin(double degrees)
    {
        if (degrees % 90 == 0)
            return (((long)(degrees / 90) % 4 + 4) % 4) switch
            {
                0 => (1, 0),
                1 => (0, 1),
                2 => (-1, 0),
                _ => (0, -1),
            };
        var radians = degrees * Math.PI / 180;
        return (Math.Cos(radians), Math.Sin(radians));
    }
}
