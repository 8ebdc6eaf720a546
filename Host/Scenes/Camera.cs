namespace QuantumRayTracing.Scenes;

/// <summary>A pinhole camera.</summary>
/// <param name="Position">Eye position in world units (need not lie on the grid).</param>
/// <param name="LookAt">The point the view centre passes through.</param>
/// <param name="Up">Roughly up in the image; not parallel to the view direction.</param>
/// <param name="VerticalFov">Vertical field of view in degrees, in (0, 180).</param>
public sealed record Camera(Vec3 Position, Vec3 LookAt, Vec3 Up, double VerticalFov);
