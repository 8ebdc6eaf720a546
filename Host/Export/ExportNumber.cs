using System.Globalization;

namespace QuantumRayTracing.Export;

/// <summary>Numbers as exports write them, in the header and in the Q# expression: round-trip digits, so nothing is rounded.</summary>
public static class ExportNumber
{
    public static string Text(double value) => value.ToString("R", CultureInfo.InvariantCulture);

    public static string Text(int value) => value.ToString(CultureInfo.InvariantCulture);

    /// <summary>A Q# Double array literal holding the values exactly (each with a point or an exponent).</summary>
    public static string QSharpDoubles(IEnumerable<double> values) => $"[{string.Join(", ", values.Select(QSharpDouble))}]";

    /// <summary>A Q# Double literal holding the value exactly (round-trip digits, always with a point or an exponent).</summary>
    public static string QSharpDouble(double value)
    {
        var text = Text(value);
        return text.Contains('.') || text.Contains('E') ? text : text + ".0";
    }
}
