namespace QuantumRayTracing.Bridge;

/// <summary>
/// The Q# types the host constructs in its calls, by full name: the "types" of Quantum/entry-points.json,
/// checked against the sources by the Q# build like <see cref="QSharpOperations"/>.
/// </summary>
public static class QSharpTypes
{
    public const string IntersectionInput = "QuantumRayTracing.Intersection.IntersectionInput";

    public const string OracleConstruction = "QuantumRayTracing.Intersection.OracleConstruction";
}
