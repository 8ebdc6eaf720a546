using QuantumRayTracing.Experiments;
using QuantumRayTracing.Tests.Cli;
using QuantumRayTracing.Cli;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>`bench supersampling-results` checks every file its report writes before the work: one it did not write stops it at once.</summary>
public sealed class BenchSupersamplingResultsCommandTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-bench-supersample");

    public void Dispose() => _scratch.Dispose();

    [Theory]
    [InlineData("supersampling-results-qcoin-k.png")]
    [InlineData("supersampling-results.csv")]
    public void AFileItDidNotWriteBesideTheReportStopsItBeforeTheWork(string foreign)
    {
        File.WriteAllText(_scratch.File(foreign), "someone's file\n");
        var (code, error) = ConsoleCapture.Run("bench", "supersampling-results", "--trials", "10", "-o", _scratch.File("supersampling-results.md"));
        Assert.Equal(ExitCodes.BadInput, code);
        // The experiment's first progress line would show the work had started (the writer refuses too, but after it).
        Assert.DoesNotContain("error against queries", error);
        Assert.Contains(foreign, error);
        Assert.Equal([foreign], _scratch.FileNames());
        Assert.Equal("someone's file\n", File.ReadAllText(_scratch.File(foreign)));
    }
}
