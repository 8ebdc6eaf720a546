using System.Diagnostics;
using QuantumRayTracing.Export;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// The formats read back by other tools: OpenQASM 2 and 3 run on the QDK's OpenQASM import (the device
/// experiment's header promises index 2 with probability 1; a search's OpenQASM 3 against its header by
/// shot counts), QIR through LLVM's assembler when it is installed and through our reader.
/// </summary>
public sealed class ExportFormatsTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-export-formats-");

    public void Dispose() => _scratch.Dispose();

    /// <summary>The file `qrt <paramref name="arguments"/> -o FILE` writes (<see cref="ExportCache"/>: made once per test run).</summary>
    private static string Export(params string[] arguments) => ExportCache.File(arguments);

    /// <summary>The search for pixel (3, 0) of the 2-bit-grid test scene (one of 5 marked) in <paramref name="format"/>: its file and text.</summary>
    private static (string File, string Text) ExportTinySearch(string format)
    {
        var file = Export("export", "search", OpenQasmOnQuantumCircuitTests.TinyScene(), "--size", "4", "--pixel", "3,0", "--format", format);
        return (file, File.ReadAllText(file));
    }

    [Theory]
    [InlineData("qasm2")]
    [InlineData("qasm3")]
    public void DeviceExperimentRunsOnTheQdkAsItsHeaderSays(string format)
    {
        var file = Export("export", "device-experiment", "--format", format);
        var ideal = ExportedDistribution.FromHeader(file);
        Assert.True(Math.Abs(ideal[2] - 1) <= 1e-9, $"header: {string.Join(' ', ideal)}");
        // 100 shots all reading 2; a circuit that did not amplify (uniform: 1/4 each) passes with probability 4^-100.
        var shots = IndexShots(file, 100);
        Assert.Equal([2], shots.Keys);
        Assert.Equal(100, shots[2]);
    }

    /// <summary>
    /// The 5-square search (pixel (3, 0), r = 1) as OpenQASM 3 keeps the feedback of its comparators' ANDs and runs
    /// on the QDK's OpenQASM import as its header says: index 3 with probability 0.968, 0, 1, 2 and 4 with 0.008
    /// each, 5 to 7 (past N = 5, which the preparation never reaches) never. The QDK's shots take no seed, so the
    /// check is statistical, with bounds whose false-failure rate is below 1e-10 in all (exact binomial tails of
    /// 200 shots): no shot on a value the header leaves off, at least 170 on index 3 (mean 193.6: at most 30 misses
    /// where 6.4 are expected, probability 5e-13), at most 15 on each other value (mean 1.6, probability 1.2e-11 each,
    /// 4.8e-11 for the four). The same search with r = 0 (index 3 with probability 0.2, 40 shots expected) must fail
    /// the bounds; it passes them with probability below 1e-86.
    /// </summary>
    [Fact]
    public void SearchQasm3RunsOnTheQdkAsItsHeaderSays()
    {
        var (file, text) = ExportTinySearch("qasm3");
        Assert.Contains("if (uncompute) { cz ", text, StringComparison.Ordinal);
        var ideal = ExportedDistribution.FromHeader(file);
        Assert.True(Math.Abs(ideal[3] - 0.968) <= 1e-9, $"header: {string.Join(' ', ideal)}");
        Assert.Null(MissedBounds(ideal, IndexShots(file, Shots)));
        var none = Export("export", "search", OpenQasmOnQuantumCircuitTests.TinyScene(), "--size", "4", "--pixel", "3,0", "--iterations", "0", "--format", "qasm3");
        Assert.NotNull(MissedBounds(ideal, IndexShots(none, Shots)));
    }

    /// <summary>Shots of the 5-square search on the QDK: what the bounds above need.</summary>
    private const int Shots = 200;

    /// <summary>What <see cref="Shots"/> shots of the 5-square search break of the bounds its header sets (above); null: none.</summary>
    private static string? MissedBounds(IReadOnlyDictionary<int, double> ideal, Dictionary<int, int> shots)
    {
        var seen = string.Join(' ', shots.OrderBy(s => s.Key));
        if (shots.Keys.Any(v => !ideal.ContainsKey(v))) return $"a shot on a value the header leaves off: {seen}";
        if (shots.GetValueOrDefault(3) < 170) return $"index 3 read {shots.GetValueOrDefault(3)} times in {Shots}, expected about 193.6: {seen}";
        if (shots.Any(s => s.Key != 3 && s.Value > 15)) return $"another index read more than 15 times in {Shots}: {seen}";
        return null;
    }

    /// <summary>
    /// How often each value of the index register is read in <paramref name="count"/> shots of the file on the QDK's
    /// OpenQASM import. A shot prints the file's bit registers, the index first (bit 0 first): "[Zero, One]", or
    /// "([Zero, One], One)" when an OpenQASM 3 file also declares its bit uncompute.
    /// </summary>
    private static Dictionary<int, int> IndexShots(string file, int count)
    {
        var histogram = NodeScript.Run("qdk-openqasm.mjs", file, "--shots", count.ToString(System.Globalization.CultureInfo.InvariantCulture))["shots"]!.AsObject();
        var byIndex = new Dictionary<int, int>();
        foreach (var (key, value) in histogram)
        {
            var bits = key[(key.IndexOf('[', StringComparison.Ordinal) + 1)..key.IndexOf(']', StringComparison.Ordinal)].Split(", ");
            var index = bits.Select((bit, k) => bit == "One" ? 1 << k : 0).Sum();
            byIndex[index] = byIndex.GetValueOrDefault(index) + value!.GetValue<int>();
        }
        Assert.Equal(count, byIndex.Values.Sum());
        return byIndex;
    }

    [Fact]
    public void SearchQirAssemblesAndRecordsTheIndexRegister()
    {
        var (file, text) = ExportTinySearch("qir");
        Assert.StartsWith("; QuantumRayTracing: ", text, StringComparison.Ordinal);
        Assert.Contains("\n; ideal outcome probabilities: 3:0.96", text, StringComparison.Ordinal);
        Assert.Contains("\"qir_profiles\"=\"adaptive_profile\"", text, StringComparison.Ordinal);
        Assert.Equal(3, QirReader.Read(text).Outputs.Count);
        if (OnPath("llvm-as") is { } assembler)
        {
            var start = new ProcessStartInfo(assembler) { RedirectStandardError = true };
            start.ArgumentList.Add(file);
            start.ArgumentList.Add("-o");
            start.ArgumentList.Add(_scratch.File("search.bc"));
            using var process = Process.Start(start)!;
            var error = process.StandardError.ReadToEnd();
            process.WaitForExit();
            Assert.True(process.ExitCode == 0, error);
        }
    }

    [Fact]
    public void QssQasm3RunsOnTheQdkAsItsHeaderSays()
    {
        // Mean 0.5: θ = π/4 sits on the grid of t = 2, so the header promises readouts 1 and 3, one half each.
        var file = Export("export", "qss", "--values", "0.25", "0.75", "--counter-bits", "2", "--format", "qasm3");
        var ideal = ExportedDistribution.FromHeader(file);
        Assert.True(Math.Abs(ideal[1] - 0.5) <= 1e-9 && Math.Abs(ideal[3] - 0.5) <= 1e-9, $"header: {string.Join(' ', ideal)}");
        Assert.Contains("bit[2] counter;", File.ReadAllText(file), StringComparison.Ordinal);
        // 100 shots, bit 0 first: every one must read 1 or 3 (a wrong circuit that gives 0 or 2 with probability q
        // passes with (1 - q)^100), and both must occur (false failure 2^-99).
        var shots = NodeScript.Run("qdk-openqasm.mjs", file, "--shots", "100")["shots"]!.AsObject();
        Assert.Equal(["[One, One]", "[One, Zero]"], shots.Select(s => s.Key).Order(StringComparer.Ordinal));
        Assert.Equal(100, shots.Sum(s => s.Value!.GetValue<int>()));
    }

    [Fact]
    public void QssQirRecordsTheCounterOnly()
    {
        var text = File.ReadAllText(Export("export", "qss", "--values", "0", "1", "1", "1", "--format", "qir"));
        Assert.Contains("\"qir_profiles\"=\"adaptive_profile\"", text, StringComparison.Ordinal);
        var circuit = QirReader.Read(text);
        Assert.Equal(3, circuit.Outputs.Count);
        Assert.True(circuit.Qubits >= 3 + 2 + 1, $"{circuit.Qubits} qubits hold no counter, subpixel and coin registers");
    }

    private static string? OnPath(string tool) =>
        (Environment.GetEnvironmentVariable("PATH") ?? "").Split(Path.PathSeparator).Select(d => Path.Combine(d, tool)).FirstOrDefault(File.Exists);
}
