using System.Text.Json.Nodes;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>
/// Standard output redirected to a file or pipe (as here: the test reads it) gets no escape codes and no wrapping,
/// even when TERM claims a colour terminal: every printed line reads as one line.
/// </summary>
public sealed class PlainOutputTests : IDisposable
{
    private static readonly Dictionary<string, string> ColourTerminal = OneRayEstimate.ColourTerminal;

    private readonly ScratchDirectory _scratch = new("qrt-plain-");

    public void Dispose() => _scratch.Dispose();

    [Fact]
    public void RenderPrintsPlainUnwrappedLines()
    {
        var (code, output, error) = QrtProcess.Run(ColourTerminal, _scratch.Path, "render", "--size", "16", "-o", "r.png");
        Assert.True(code == 0, error);
        Assert.DoesNotContain('\u001b', output);
        var lines = output.Split('\n');
        // The two longest sentences render prints, each whole on one line (at 80 columns both were broken).
        Assert.Contains(lines, l => l.StartsWith("error against the classical render: NRMSE ", StringComparison.Ordinal) && l.Contains("%Dpix", StringComparison.Ordinal));
        Assert.Contains(lines, l => l.StartsWith("#Eval: conservative counts r + 1", StringComparison.Ordinal) && l.TrimEnd().EndsWith("are not in Int/Ray.", StringComparison.Ordinal));
        Assert.Contains(lines, l => l.StartsWith("Qornell box, 64 primitives: N = 64", StringComparison.Ordinal) && l.Contains("integer grid", StringComparison.Ordinal));
    }

    [Fact]
    public void EstimateTableKeepsEachLabelOnOneLine()
    {
        var (code, output, error, _) = OneRayEstimate.Result;
        Assert.True(code == 0, error);
        Assert.DoesNotContain('\u001b', output);
        var rows = output.Split('\n').Where(l => l.StartsWith('│')).Select(l => l.Split('│')[1].Trim()).ToArray();
        Assert.Contains("modelled: index + work + output + auxiliary", rows);
        Assert.Contains("qubit_gate_ns_e3, surface_code: physical qubits", rows);
        // A wrapped label would leave a row whose first cell continues the one above.
        Assert.DoesNotContain("", rows);
    }

    [Fact]
    public void VersionNamesTheProgramTheQdkAndNode()
    {
        var (code, output, error) = QrtProcess.Run(new Dictionary<string, string>(), _scratch.Path, "--version");
        Assert.True(code == 0, error);
        var lines = output.TrimEnd().Split('\n');
        Assert.Equal(3, lines.Length);
        Assert.StartsWith("qrt 1.", lines[0], StringComparison.Ordinal);
        var pinned = JsonNode.Parse(File.ReadAllText(Path.Combine(RepositoryPaths.Root, "Quantum", "package.json")))!["dependencies"]!["qsharp-lang"]!.GetValue<string>();
        Assert.Equal($"QDK: qsharp-lang {pinned}", lines[1]);
        Assert.Matches(@"^Node\.js: v\d+\.\d+\.\d+$", lines[2]);
    }

    [Fact]
    public void VersionSaysWhenNodeIsMissingAndStillSucceeds()
    {
        var missing = Path.Combine(_scratch.Path, "no-node-here");
        var (code, output, error) = QrtProcess.Run(new Dictionary<string, string> { ["QRT_NODE"] = missing }, _scratch.Path, "--version");
        Assert.True(code == 0, error);
        Assert.Contains($"Node.js: not found: could not start '{missing}'", output, StringComparison.Ordinal);
        Assert.Equal("", error);
    }
}
