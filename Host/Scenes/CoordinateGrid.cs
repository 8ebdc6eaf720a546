namespace QuantumRayTracing.Scenes;

/// <summary>
/// The fixed-point grid every primitive coordinate lies on: values k / 2^FractionBits for integers
/// 0 ≤ k &lt; 2^(IntegerBits + FractionBits). The paper's 16x16x16 world is 4 integer bits, no fraction.
/// Registers holding a coordinate need <see cref="Bits"/> qubits.
/// </summary>
public readonly record struct CoordinateGrid(int IntegerBits, int FractionBits)
{
    public const int MaxBits = 16;

    /// <summary>Qubits per coordinate.</summary>
    public int Bits => IntegerBits + FractionBits;

    /// <summary>Distance between neighbouring grid values.</summary>
    public double Step => 1.0 / (1 << FractionBits);

    /// <summary>Largest grid value, (2^Bits − 1) · Step.</summary>
    public double Max => ((1 << Bits) - 1) * Step;

    /// <summary>The grid integer k of an exact grid value, or null when the value is off the grid.</summary>
    public int? ToFixed(double value)
    {
        var scaled = value * (1 << FractionBits);
        if (!double.IsFinite(scaled) || scaled != Math.Floor(scaled) || scaled < 0 || scaled >= 1 << Bits) return null;
        return (int)scaled;
    }

    public override string ToString() => FractionBits == 0
        ? $"{IntegerBits}-bit integer grid 0..{Max}"
        : $"{IntegerBits}.{FractionBits} fixed-point grid 0..{Max} in steps of {Step}";
}
