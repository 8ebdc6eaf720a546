using System.Diagnostics;
using QuantumRayTracing.Export;
using QuantumRayTracing.Tests.Cli;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// The formats read back by other tools: OpenQASM 2 and 3 through the QDK's OpenQASM import (the device
/// experiment's OpenQASM 2 also run there: its header promises index 2 with probability 1), QIR through
/// LLVM's assembler when it is installed and through our reader.
/// </summary>
public sealed class ExportFormatsTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-export-formats-");

    public void Dispose() => _scratch.Dispose();

    private string Export(string name, params string[] arguments)
    {
        var file = _scratch.File(name);
        var (code, error) = ConsoleCapture.Run([.. arguments, "-o", file]);
        Assert.True(code == 0, error);
        return file;
    }

    /// <summary>The search for pixel (3, 0) of the 2-bit-grid test scene (one of 5 marked) in <paramref name="format"/>: its file and text.</summary>
    private (string File, string Text) ExportTinySearch(string name, string format)
    {
        var file = Export(name, "export", "search", OpenQasmOnQuantumCircuitTests.TinyScene(_scratch), "--size", "4", "--pixel", "3,0", "--format", format);
        return (file, File.ReadAllText(file));
    }

    [Fact]
    public void DeviceExperimentQasm2RunsOnTheQdkAsItsHeaderSays()
    {
        var file = Export("device.qasm", "export", "device-experiment");
        var ideal = ExportedDistribution.FromHeader(file);
        Assert.True(Math.Abs(ideal[2] - 1) <= 1e-9, $"header: {string.Join(' ', ideal)}");
        // 100 shots all reading 2 = [bit 0 Zero, bit 1 One]; a circuit that did not amplify (uniform: 1/4 each) passes with probability 4^-100.
        var reply = NodeScript.Run("qdk-openqasm.mjs", file, "--shots", "100");
        var shots = reply["shots"]!.AsObject();
        Assert.Single(shots);
        Assert.Equal(100, shots["[Zero, One]"]!.GetValue<int>());
    }

    [Fact]
    public void SearchQasm3KeepsFeedbackAndCompilesOnTheQdk()
    {
        var (file, text) = ExportTinySearch("search3.qasm", "qasm3");
        Assert.Contains("OPENQASM 3.0;", text, StringComparison.Ordinal);
        Assert.Contains("if (uncompute) { cz ", text, StringComparison.Ordinal);
        Assert.True(NodeScript.Run("qdk-openqasm.mjs", file)["qirInstructions"]!.GetValue<int>() > 100);
    }

    [Fact]
    public void SearchQirAssemblesAndRecordsTheIndexRegister()
    {
        var (file, text) = ExportTinySearch("search.ll", "qir");
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
        var file = Export("qss3.qasm", "export", "qss", "--values", "0.25", "0.75", "--counter-bits", "2", "--format", "qasm3");
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
        var text = File.ReadAllText(Export("qss.ll", "export", "qss", "--values", "0", "1", "1", "1", "--format", "qir"));
        Assert.Contains("\"qir_profiles\"=\"adaptive_profile\"", text, StringComparison.Ordinal);
        var circuit = QirReader.Read(text);
        Assert.Equal(3, circuit.Outputs.Count);
        Assert.True(circuit.Qubits >= 3 + 2 + 1, $"{circuit.Qubits} qubits hold no counter, subpixel and coin registers");
    }

    private static string? OnPath(string tool) =>
        (Environment.GetEnvironmentVariable("PATH") ?? "").Split(Path.PathSeparator).Select(d => Path.Combine(d, tool)).FirstOrDefault(File.Exists);
}
