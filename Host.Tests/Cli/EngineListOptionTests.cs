using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>`--engines` (bench soak, bench scale): names out of the command's own list, space- or comma-separated, each kept once.</summary>
public sealed class EngineListOptionTests
{
    private static readonly EngineKind[] Allowed = [EngineKind.Classical, EngineKind.Bvh, EngineKind.Analytic];

    private static ParseResult Parse(params string[] args)
    {
        var command = new RootCommand { CommonOptions.Engines("Engines.", [EngineKind.Classical], Allowed) };
        return command.Parse(["--engines", .. args]);
    }

    [Fact]
    public void TakesNamesInAnyCaseAndSeparatorInTheListsOrder()
    {
        var parse = Parse("analytic,CLASSICAL", "bvh", "classical");
        Assert.Empty(parse.Errors);
        Assert.Equal(Allowed, parse.GetValue<EngineKind[]>("--engines"));
    }

    [Theory]
    [InlineData("gate")]      // an engine, but not one this command measures
    [InlineData("fullstate")] // the enum's first value, which a lookup defaulting to it would let through
    [InlineData("foo")]
    public void RefusesANameOutsideTheCommandsList(string name)
    {
        var error = Assert.Single(Parse(name).Errors).Message;
        Assert.Equal($"--engines: '{name}' is not one of classical, bvh, analytic", error);
    }

    [Fact]
    public void BenchScaleRefusesAnEngineItDoesNotMeasure()
    {
        var (code, error) = ConsoleCapture.Run("bench", "scale", "--engines", "gate", "-o", Path.Combine(Path.GetTempPath(), $"qrt-scale-{Guid.NewGuid():N}.md"));
        Assert.Equal(ExitCodes.UsageError, code);
        Assert.Contains("--engines: 'gate' is not one of classical, bvh, analytic, randomized", error);
    }
}
