using System.Globalization;
using System.Text.Json.Nodes;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// The distributions the check compares: the one an exported file's header promises (its "ideal outcome
/// probabilities" line), the ones two independent simulators compute from the file's gates (quantum-circuit,
/// Quantum/check-openqasm.mjs; jsqubits, Quantum/check-openqasm-jsqubits.mjs), and Grover's closed form.
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
    public static IReadOnlyDictionary<int, double> OnQuantumCircuit(string file, string register) => Simulated("check-openqasm.mjs", file, register);

    /// <summary>The measured register's distribution on jsqubits (sparse state, at most 31 qubits), checked to be register <paramref name="register"/>.</summary>
    public static IReadOnlyDictionary<int, double> OnJsqubits(string file, string register) => Simulated("check-openqasm-jsqubits.mjs", file, register);

    /// <summary>The marked primitives the header's "ray:" line lists (none: empty).</summary>
    public static int[] MarkedFromHeader(string file)
    {
        var line = File.ReadLines(file).First(l => l.StartsWith("// ray: ", StringComparison.Ordinal));
        var list = line[(line.LastIndexOf(": ", StringComparison.Ordinal) + 2)..];
        return list == "none" ? [] : list.Split(' ').Select(v => int.Parse(v, CultureInfo.InvariantCulture)).ToArray();
    }

    /// <summary>
    /// Grover's search over N items with the given marked ones after r iterations, from its closed form: each
    /// marked item sin²((2r+1)θ)/M, each unmarked one cos²((2r+1)θ)/(N−M), sin²θ = M/N; uniform 1/N when
    /// nothing is marked (every iteration leaves the uniform superposition as it is).
    /// </summary>
    public static IReadOnlyDictionary<int, double> GroverClosedForm(int count, int[] marked, int iterations)
    {
        if (marked.Length == 0) return Enumerable.Range(0, count).ToDictionary(v => v, _ => 1.0 / count);
        var theta = Math.Asin(Math.Sqrt((double)marked.Length / count));
        var hit = Math.Pow(Math.Sin((2 * iterations + 1) * theta), 2);
        return Enumerable.Range(0, count).ToDictionary(v => v, v => marked.Contains(v) ? hit / marked.Length : (1 - hit) / (count - marked.Length));
    }

    private static IReadOnlyDictionary<int, double> Simulated(string script, string file, string register)
    {
        var reply = NodeScript.Run(script, file);
        Assert.Equal(register, reply["register"]!.GetValue<string>());
        return reply["probabilities"]!.AsObject().ToDictionary(p => int.Parse(p.Key, CultureInfo.InvariantCulture), p => p.Value!.GetValue<double>());
    }

    /// <summary>
    /// How far quantum-circuit's distribution (jsqubits' with <paramref name="onJsqubits"/>) for <paramref name="file"/>
    /// with its first line matching <paramref name="dropped"/> removed (written to <paramref name="broken"/>) lies from the file's header.
    /// </summary>
    public static double HeaderDifferenceWithout(string file, Predicate<string> dropped, string register, string broken, bool onJsqubits = false)
    {
        var lines = File.ReadAllLines(file).ToList();
        lines.RemoveAt(lines.FindIndex(dropped));
        File.WriteAllLines(broken, lines);
        return MaxDifference(FromHeader(file), onJsqubits ? OnJsqubits(broken, register) : OnQuantumCircuit(broken, register));
    }

    /// <summary>
    /// Asserts that two distributions of the measured register agree within <see cref="Tolerance"/>; the failure names both
    /// (<paramref name="first"/>, <paramref name="second"/>) with their values, after <paramref name="what"/>.
    /// </summary>
    public static void AssertAgree(IReadOnlyDictionary<int, double> a, IReadOnlyDictionary<int, double> b, string first, string second, string what = "") =>
        Assert.True(MaxDifference(a, b) <= Tolerance, $"{what}{first} {string.Join(' ', a)} vs {second} {string.Join(' ', b)}");

    /// <summary>The largest difference between two distributions over any value (a value one lacks has probability 0 there).</summary>
    public static double MaxDifference(IReadOnlyDictionary<int, double> a, IReadOnlyDictionary<int, double> b) =>
        a.Keys.Union(b.Keys).Max(v => Math.Abs(a.GetValueOrDefault(v) - b.GetValueOrDefault(v)));
}
