using QuantumRayTracing.Tests.BadInput;
using QuantumRayTracing.Tests.Cli;

namespace QuantumRayTracing.Tests.Export;

/// <summary>`export`'s refusals: one line, the option named, nothing the user wrote replaced.</summary>
public sealed class ExportCommandTests : IDisposable
{
    private static readonly string Scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");

    private readonly ScratchDirectory _scratch = new("qrt-export-cli-");

    public void Dispose() => _scratch.Dispose();

    [Fact]
    public void ExistingFileIsKeptWithoutForce()
    {
        var file = _scratch.File("mine.qasm");
        File.WriteAllText(file, "mine");
        Outcome.Of("export", "device-experiment", "-o", file).AssertBadInput($"-o {file}", "the file exists; give --force to replace it");
        Assert.Equal("mine", File.ReadAllText(file));
        var (code, error) = ConsoleCapture.Run("export", "device-experiment", "-o", file, "--force");
        Assert.True(code == 0, error);
        Assert.StartsWith("// QuantumRayTracing: ", File.ReadAllText(file), StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("--oracle", "unknown construction 'smallest'", "--pixel", "1,1", "--oracle", "smallest")]
    [InlineData("--iterations", "must be between 0 and 64", "--pixel", "1,1", "--iterations", "65")]
    [InlineData("--pixel", "expected X,Y", "--pixel", "1")]
    [InlineData("--format", "'qasm4' is not one of qasm2, qasm3, qir", "--pixel", "1,1", "--format", "qasm4")]
    public void UsageErrors(string option, string problem, params string[] options) =>
        Outcome.Of(["export", "search", Scene, .. options]).AssertUsageError(option, problem);

    [Theory]
    [InlineData("--mean", "give exactly one")]
    [InlineData("--mean", "give exactly one", "--mean", "0.3", "--values", "0.1")]
    [InlineData("--mean", "must lie in [0, 1], got 2", "--mean", "2")]
    [InlineData("--values", "1.5 is outside [0, 1]", "--values", "0.1", "1.5")]
    [InlineData("--k", "must be at most 64, got 65", "--mean", "0.3", "--k", "65")]
    public void CoinUsageErrors(string option, string problem, params string[] options) =>
        Outcome.Of(["export", "coin", .. options]).AssertUsageError(option, problem);

    [Theory]
    [InlineData("--values", "is required")]
    [InlineData("--values", "1.5 is outside [0, 1]", "--values", "0.1", "1.5")]
    [InlineData("--values", "-0.2 is outside [0, 1]", "--values", "-0.2")]
    [InlineData("--counter-bits", "must be at most 6, got 7", "--values", "0.5", "--counter-bits", "7")]
    [InlineData("--counter-bits", "must be at least 1, got 0", "--values", "0.5", "-t", "0")]
    public void QssUsageErrors(string option, string problem, params string[] options) =>
        Outcome.Of(["export", "qss", .. options]).AssertUsageError(option, problem);

    [Fact]
    public void PixelOutsideTheImageIsBadInput() =>
        Outcome.Of("export", "search", Scene, "--size", "8", "--pixel", "8,0").AssertBadInput("--pixel 8,0", "is outside the 8x8 image");
}
