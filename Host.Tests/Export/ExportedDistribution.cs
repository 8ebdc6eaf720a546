using System.Globalization;
using System.Text.Json.Nodes;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// The two distributions the check compares: the one an exported file's header promises (its "ideal outcome
/// probabilities" line) and the one quantum-circuit computes from the file's gates (Quantum/check-openqasm.mjs).
/// </summary>
internal static class ExportedDistribution
{
    /// <summary>How far the two may differ: both are exact state vectors, so only rounding separates them.</summary>
    public const double Tolerance = 1e-9;

    /// <summary>Value → probability from the header line "// ideal outcome probabilities: V:P V:P ...".</summary>
    public static IReadOnlyDictionary<int, double> FromHeader(string file)
    {
        var line = File.ReadLines(file).First(l => l.StartsWith("// ideal outcome probabilities: ", StringComparison.Ordinal));
        return line["// ideal outcome probabilities: ".Length..].Split(' ', StringSplitOptions.RemoveEmptyEntries)
            .Select(pair => pair.Split(':'))
            .ToDictionary(p => int.Parse(p[0], CultureInfo.InvariantCulture), p => double.Parse(p[1], CultureInfo.InvariantCulture));
    }

    /// <summary>The measured register's distribution on quantum-circuit, checked to be register <paramref name="register"/>.</summary>
    public static IReadOnlyDictionary<int, double> OnQuantumCircuit(string file, string register)
    {
        var reply = NodeScript.Run("check-openqasm.mjs", file);
        Assert.Equal(register, reply["register"]!.GetValue<string>());
        return reply["probabilities"]!.AsObject().ToDictionary(p => int.Parse(p.Key, CultureInfo.InvariantCulture), p => p.Value!.GetValue<double>());
    }

    /// <summary>
    /// How far quantum-circuit's distribution for <paramref name="file"/> with its first line matching
    /// <paramref name="dropped"/> removed (written to <paramref name="broken"/>) lies from the file's header.
    /// </summary>
    public static double HeaderDifferenceWithout(string file, Predicate<string> dropped, string register, string broken)
    {
        var lines = File.ReadAllLines(file).ToList();
        lines.RemoveAt(lines.FindIndex(dropped));
        File.WriteAllLines(broken, lines);
        return MaxDifference(FromHeader(file), OnQuantumCircuit(broken, register));
    }

    /// <summary>The largest difference between two distributions over any value (a value one lacks has probability 0 there).</summary>
    public static double MaxDifference(IReadOnlyDictionary<int, double> a, IReadOnlyDictionary<int, double> b) =>
        a.Keys.Union(b.Keys).Max(v => Math.Abs(a.GetValueOrDefault(v) - b.GetValueOrDefault(v)));
}
