using QuantumRayTracing.Experiments;
using Xunit;

namespace QuantumRayTracing.Tests.Experiments.FrameSweep;

public class RuntimeScalingTests
{
    private static readonly int[] Primitives = [8, 16, 32, 64, 128];

    [Fact]
    public void ExactPowerLawsAreFittedWithoutResidualAndCrossWhereTheyAreEqual()
    {
        // quantum 2e-3 · N^1.5 s, classical 0.25 · N^0.5 s: equal where N = 0.25 / 2e-3 = 125.
        var quantum = Primitives.Select(n => 2e-3 * Math.Pow(n, 1.5)).ToArray();
        var classical = Primitives.Select(n => 0.25 * Math.Sqrt(n)).ToArray();
        var row = Assert.Single(RuntimeScaling.Fit(Primitives, [("model", quantum)], classical));
        Assert.Equal(1.5, row.Quantum.Exponent, 9);
        Assert.Equal(0.5, row.Classical.Exponent, 9);
        Assert.Equal(0, row.Quantum.Residual, 9);
        Assert.Equal(125, row.Crossing!.Value, 6);
        Assert.Equal((8, 128), (row.Quantum.From, row.Quantum.To));
        Assert.StartsWith("N ≈ 125, inside the measured range; quantum faster below it", row.CrossingText(), StringComparison.Ordinal);
    }

    [Fact]
    public void CrossingsBelowOneAreNoneBeyondTheMeasuredNAnExtrapolationAndParallelFitsNeverCross()
    {
        var quantum = Primitives.Select(n => 1e3 * Math.Pow(n, 1.2)).ToArray();
        var classical = Primitives.Select(n => 1e-4 * Math.Pow(n, 0.7)).ToArray();
        var row = Assert.Single(RuntimeScaling.Fit(Primitives, [("model", quantum)], classical));
        Assert.Equal(Math.Pow(1e-7, 1 / 0.5), row.Crossing!.Value, 1e-20);
        Assert.StartsWith("none at any N ≥ 1", row.CrossingText(), StringComparison.Ordinal);
        // Meeting beyond the measured N is an extrapolation: classical 1e-4 · N^0.7 against 1e-6 · N^1.2 meet at N = 1e4.
        var late = Assert.Single(RuntimeScaling.Fit(Primitives, [("model", Primitives.Select(n => 1e-6 * Math.Pow(n, 1.2)).ToArray())], classical));
        Assert.Equal(1e4, late.Crossing!.Value, 1e-6);
        Assert.Contains("outside the measured range (an extrapolation of the fits); quantum faster below it", late.CrossingText(), StringComparison.Ordinal);

        var parallel = Assert.Single(RuntimeScaling.Fit(Primitives, [("model", classical.Select(c => 5 * c).ToArray())], classical));
        Assert.Null(parallel.Crossing);
        Assert.StartsWith("none", parallel.CrossingText(), StringComparison.Ordinal);
    }

    [Fact]
    public void TheResidualIsTheRootMeanSquareOfTheLogResiduals()
    {
        // y = N^1 times 10^(±0.1) alternately: the least-squares line through symmetric scatter keeps slope 1 only on average,
        // so check the residual against the definition instead: RMS of log10 y − fit.
        double[] x = [1, 10, 100, 1000];
        double[] y = [Math.Pow(10, 0.1), 10 * Math.Pow(10, -0.1), 100 * Math.Pow(10, -0.1), 1000 * Math.Pow(10, 0.1)];
        var fit = LogLogFit.Of(x.Zip(y))!;
        var rms = Math.Sqrt(x.Zip(y).Average(p => Math.Pow(Math.Log10(p.Second) - Math.Log10(fit.At(p.First)), 2)));
        Assert.Equal(rms, fit.Residual, 12);
        Assert.Equal(0.1, fit.Residual, 12);
        Assert.Equal(1, fit.Exponent, 12);
    }
}
