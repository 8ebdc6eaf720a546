using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cli;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>
/// Failures of Node.js, the bridge, Q# and our own code reach the user as an explanation and an exit
/// code, never as a stack trace; --verbose adds the details. Each case runs `qrt` as a process with
/// a stand-in for Node.js named by QRT_NODE.
/// </summary>
public sealed class FailureReportTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-failures-");

    private static readonly string[] Search = ["search", "-n", "8", "-s", "1", "--engine", "fullstate", "--workers", "1"];

    [Fact]
    public void MissingNodeIsExplainedWithoutAStackTrace()
    {
        var node = new Dictionary<string, string> { [BridgeOptions.NodeVariable] = _scratch.File("no-such-node") };

        var (code, _, error) = QrtProcess.Run(node, _scratch.Path, Search);

        Assert.Equal(ExitCodes.QuantumFailure, code);
        var lines = Lines(error);
        Assert.StartsWith("error: could not start Node.js", lines[0]);
        Assert.Contains(BridgeOptions.NodeVariable, lines[0]);
        Assert.Contains("--verbose", lines[1]);
        Assert.Equal(2, lines.Length);

        var verbose = QrtProcess.Run(node, _scratch.Path, [.. Search, "--verbose"]);
        Assert.Equal(ExitCodes.QuantumFailure, verbose.Code);
        Assert.Contains("   at QuantumRayTracing.Bridge.QSharpBridge", verbose.Error);
    }

    [Fact]
    public void CrashingBridgeIsExplainedAndItsOutputShownOnlyWhenVerbose()
    {
        var node = FakeNode("crash", "echo 'simulated crash in the simulator' >&2\nexit 7");

        var (code, _, error) = QrtProcess.Run(node, _scratch.Path, Search);

        Assert.Equal(ExitCodes.QuantumFailure, code);
        var lines = Lines(error);
        Assert.StartsWith("error: the Node process running the Q# simulator crashed twice", lines[0]);
        Assert.Equal(2, lines.Length);
        Assert.DoesNotContain("simulated crash", error);

        var verbose = QrtProcess.Run(node, _scratch.Path, [.. Search, "--verbose"]);
        Assert.Contains("simulated crash in the simulator", verbose.Error);
        Assert.Contains("   at ", verbose.Error);
    }

    [Fact]
    public void QSharpFailureNamesItsLocationAndShowsTheQSharpStackOnlyWhenVerbose()
    {
        // Starts like the bridge, then answers every request with a Q# runtime failure.
        var version = QuantumProject.PinnedQSharpVersion(QuantumProject.BridgeScript) ?? "unknown";
        var node = FakeNode("qsharp-failure", $$$"""
            echo '{"ready":true,"qsharp":"{{{version}}}"}'
            while read -r line; do
              id=$(echo "$line" | sed 's/.*"id":\([0-9]*\).*/\1/')
              echo "{\"id\":$id,\"ok\":false,\"error\":{\"kind\":\"qsharp\",\"message\":\"Error: program failed: simulated failure\",\"location\":\"src/Search/MeasureGroverSearch.qs:30:13\",\"stack\":\"  at QuantumRayTracing.Search.MeasureGroverSearch\"}}"
            done
            """);

        var (code, _, error) = QrtProcess.Run(node, _scratch.Path, Search);

        Assert.Equal(ExitCodes.QuantumFailure, code);
        var lines = Lines(error);
        Assert.Equal("error: Q# failed at src/Search/MeasureGroverSearch.qs:30:13: Error: program failed: simulated failure", lines[0]);
        Assert.Equal(2, lines.Length);

        var verbose = QrtProcess.Run(node, _scratch.Path, [.. Search, "--verbose"]);
        Assert.Contains("Q# call stack:", verbose.Error);
        Assert.Contains("at QuantumRayTracing.Search.MeasureGroverSearch", verbose.Error);
    }

    [Fact]
    public void TooWideASearchIsRefusedBeforeAnyBridgeStarts()
    {
        // With no Node.js at all, reaching a bridge would fail with exit code 3: code 2 shows the refusal came first.
        var node = new Dictionary<string, string> { [BridgeOptions.NodeVariable] = _scratch.File("no-such-node") };

        var search = QrtProcess.Run(node, _scratch.Path, "search", "-n", "64", "--engine", "fullstate", "--max-qubits", "6");
        Assert.Equal(ExitCodes.BadInput, search.Code);
        Assert.Equal("error: a search over N = 64 indices needs 10 qubits (2^6 amplitudes, about 5.0 KiB of simulator memory per worker), more than the limit of 6 (--max-qubits; the default is the widest state this machine holds: a WebAssembly heap of at most 4 GiB per worker)",
            Reported(search.Error).Single());

        var render = QrtProcess.Run(node, _scratch.Path, "render", "--engine", "fullstate", "--size", "4", "--max-qubits", "9", "-o", "out.png");
        Assert.Equal(ExitCodes.BadInput, render.Code);
        Assert.Contains("needs 10 qubits", Reported(render.Error).Single());
        Assert.Empty(Directory.EnumerateFileSystemEntries(_scratch.Path));

        var supersample = QrtProcess.Run(node, _scratch.Path, "supersample", "--engine", "fullstate", "--size", "2", "--max-qubits", "8", "-o", "out.png");
        Assert.Equal(ExitCodes.BadInput, supersample.Code);
        Assert.Contains("a QSS readout with 4 counter bits over 16 subpixels needs 9 qubits", Reported(supersample.Error).Single());
        Assert.Empty(Directory.EnumerateFileSystemEntries(_scratch.Path));
    }

    [Fact]
    public void UnexpectedExceptionIsReportedAsAnInternalErrorWithItsStackOnlyWhenVerbose()
    {
        Exception thrown;
        try
        {
            throw new InvalidOperationException("an impossible state");
        }
        catch (InvalidOperationException e)
        {
            thrown = e;
        }

        var (code, text) = ErrorReport.Describe(thrown, verbose: false);
        Assert.Equal(ExitCodes.InternalError, code);
        Assert.Equal(["error: internal error (InvalidOperationException): an impossible state. This is a bug in QuantumRayTracing", "(run again with --verbose for the details)"], Lines(text));

        var (_, verbose) = ErrorReport.Describe(thrown, verbose: true);
        Assert.Contains(nameof(UnexpectedExceptionIsReportedAsAnInternalErrorWithItsStackOnlyWhenVerbose), verbose);
    }

    /// <summary>A shell script standing in for Node.js (it ignores the bridge script it is given).</summary>
    private Dictionary<string, string> FakeNode(string name, string body)
    {
        var path = _scratch.File(name);
        File.WriteAllText(path, "#!/bin/sh\n" + body.ReplaceLineEndings("\n") + "\n");
        if (!OperatingSystem.IsWindows()) File.SetUnixFileMode(path, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
        return new Dictionary<string, string> { [BridgeOptions.NodeVariable] = path };
    }

    private static string[] Lines(string text) => text.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);

    // Standard error less the progress lines a slow start may print after a second ("label: stage 0%", Views/ConsoleProgress):
    // what the run reports, which must be its one error line.
    private static string[] Reported(string text) =>
        [.. Lines(text).Where(line => !System.Text.RegularExpressions.Regex.IsMatch(line, @"^[^:]+: .+ \d+%(, about \d+ s left)?$"))];

    public void Dispose() => _scratch.Dispose();
}
