namespace QuantumRayTracing.Intersection;

/// <summary>
/// Everything the gate-level intersection oracle loads for one search: the primitives' bounds (from
/// the table's geometry), the ray's table and the window of accepted (depth, id); and how the oracle
/// is built (<see cref="Construction"/>, which does not change the rows it marks).
/// </summary>
public sealed record OracleInput(RayTable Table, HitWindow Window)
{
    public SceneGeometry Geometry => Table.Geometry;

    public OracleConstruction Construction { get; init; } = OracleConstruction.Default;
}
