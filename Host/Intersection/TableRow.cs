namespace QuantumRayTracing.Intersection;

/// <summary>
/// One row of a ray's lookup table: whether the ray meets the primitive's plane at a grid point
/// (<see cref="Valid"/>), the quantised point, its depth along the ray's principal axis and the ray
/// parameter t of the unquantised point.
/// </summary>
public readonly record struct TableRow(bool Valid, int X, int Y, int Z, int Depth, double Distance);
