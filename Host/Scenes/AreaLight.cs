namespace QuantumRayTracing.Scenes;

/// <summary>
/// A rectangular emitter: axis-aligned, flat on <see cref="FlatAxis"/>, emitting <see cref="Radiance"/>
/// (RGB, ≥ 0) uniformly from both faces. It is not a primitive: rays pass through it and it occludes
/// nothing, so it may lie anywhere, on the grid or off it (docs/scenes.md).
/// </summary>
public sealed record AreaLight(Vec3 Min, Vec3 Max, int FlatAxis, Vec3 Radiance)
{
    /// <summary>The two in-plane axes, in increasing order.</summary>
    public (int U, int V) PlaneAxes => FlatAxis switch { 0 => (1, 2), 1 => (0, 2), _ => (0, 1) };

    public double Area => (Max[PlaneAxes.U] - Min[PlaneAxes.U]) * (Max[PlaneAxes.V] - Min[PlaneAxes.V]);

    /// <summary>The unit normal along +<see cref="FlatAxis"/>; the light emits on both sides of it.</summary>
    public Vec3 Normal => FlatAxis switch { 0 => new Vec3(1, 0, 0), 1 => new Vec3(0, 1, 0), _ => new Vec3(0, 0, 1) };

    /// <summary>The point at fractions (<paramref name="u"/>, <paramref name="v"/>) ∈ [0, 1]² of the two in-plane sides.</summary>
    public Vec3 PointAt(double u, double v)
    {
        var (a, b) = PlaneAxes;
        Span<double> p = [Min.X, Min.Y, Min.Z];
        p[a] = Min[a] + u * (Max[a] - Min[a]);
        p[b] = Min[b] + v * (Max[b] - Min[b]);
        return new Vec3(p[0], p[1], p[2]);
    }
}
