using QuantumRayTracing.Output.Plots;

namespace QuantumRayTracing.Tests.Output.Plots;

public class TickTests
{
    [Theory]
    [InlineData(0.01, "0.01")]
    [InlineData(100, "100")]
    [InlineData(1e-6, "1e-6")]
    [InlineData(1e7, "1e7")]
    [InlineData(-2.5e-8, "-2.5e-8")]
    [InlineData(0.1 + 0.2, "0.3")]
    [InlineData(123456, "123456")]
    [InlineData(0.001, "0.001")]
    [InlineData(1e-300, "1e-300")]
    [InlineData(0, "0")]
    public void CompactLabelsArePlainInTheMiddleAndScientificOutside(double value, string label) =>
        Assert.Equal(label, TickLabels.Compact(value));

    [Theory]
    [InlineData(-3, "0.001")]
    [InlineData(5, "100000")]
    [InlineData(6, "1e6")]
    [InlineData(-4, "1e-4")]
    [InlineData(309, "1e309")]
    [InlineData(-330, "1e-330")]
    public void PowersOfTenAreLabelledFromTheirExponent(int exponent, string label) =>
        Assert.Equal(label, TickLabels.PowerOfTen(exponent));

    [Theory]
    [InlineData(0.5, 0.5, false, "0.5")]
    [InlineData(0.0, 0.5, false, "0.0")]
    [InlineData(0.30000000000000004, 0.1, false, "0.3")]
    [InlineData(40, 20, false, "40")]
    [InlineData(3e6, 1e6, true, "3e6")]
    [InlineData(1.5e6, 5e5, true, "1.5e6")]
    [InlineData(-2e-6, 1e-6, true, "-2e-6")]
    [InlineData(0, 1e-6, true, "0")]
    public void MultiplesOfAStepShowJustTheStepsPrecision(double value, double step, bool scientific, string label) =>
        Assert.Equal(label, TickLabels.Multiple(value, step, scientific));

    [Fact]
    public void NegativeZeroIsLabelledAsZero() =>
        // Math.Ceiling(-0.37) is -0, which is where the first tick of a range starting just below 0 comes from.
        Assert.Equal("0.0", TickLabels.Multiple(Math.Ceiling(-0.37), 0.5, false));

    [Theory]
    [InlineData(0.13, 0.2)]
    [InlineData(3, 5)]
    [InlineData(7, 10)]
    [InlineData(1, 1)]
    [InlineData(0.0042, 0.005)]
    [InlineData(1.2e9, 2e9)]
    public void NiceStepsAreOneTwoOrFiveTimesAPowerOfTen(double raw, double step) =>
        Assert.Equal(step, AxisTicks.NiceStep(raw), 1e-12 * step);

    [Fact]
    public void StepsRunThroughOneTwoFive()
    {
        var steps = new List<double> { 0.01 };
        for (var i = 0; i < 6; i++) steps.Add(AxisTicks.NextStep(steps[^1]));
        Assert.Equal([0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1], steps.Select(s => Math.Round(s, 12)));
        Assert.Equal(0.5, AxisTicks.PreviousStep(1), 12);
        Assert.Equal(2, AxisTicks.PreviousStep(5), 12);
    }

    [Fact]
    public void LinearTicksAreEvenMultiplesOfANiceStepInsideTheRange()
    {
        var axis = new PlotAxis(AxisScale.Linear, (-0.37, 9.8), 0, 600);
        // About one tick per 50 pixels asks for a step of at least 10.17 / 12: the nice step is 1.
        var ticks = AxisTicks.For(axis, 50, _ => true);
        Assert.Equal(["0", "1", "2", "3", "4", "5", "6", "7", "8", "9"], ticks.Select(t => t.Label));
        Assert.All(ticks, t => Assert.True(t.Major));
    }

    [Fact]
    public void LinearTicksGetCoarserUntilTheLabelsFit()
    {
        var axis = new PlotAxis(AxisScale.Linear, (0, 100), 0, 500);
        // Labels "fit" only when at most four are labelled.
        var ticks = AxisTicks.For(axis, 10, t => t.Count(x => x.Label is not null) <= 4);
        Assert.Equal(["0", "50", "100"], ticks.Select(t => t.Label));
    }

    [Fact]
    public void LogTicksArePowersOfTenWithMinorTicksBetween()
    {
        var axis = new PlotAxis(AxisScale.Log10, (-6.2, 3.1), 0, 900);
        var ticks = AxisTicks.For(axis, 50, _ => true);
        var majors = ticks.Where(t => t.Major).OrderBy(t => t.At).ToList();
        Assert.Equal(["1e-6", "1e-5", "1e-4", "0.001", "0.01", "0.1", "1", "10", "100", "1000"], majors.Select(t => t.Label));
        Assert.Equal(Enumerable.Range(-6, 10).Select(k => (double)k), majors.Select(t => t.At));
        // 2..9 times each power inside the range: 8 per full decade, 2e-7 to 9e-7 below 1e-6 where >= 10^-6.2.
        var minors = ticks.Where(t => !t.Major).Select(t => Math.Pow(10, t.At)).ToList();
        Assert.Contains(minors, m => Math.Abs(m / 2e-3 - 1) < 1e-9);
        Assert.Contains(minors, m => Math.Abs(m / 900 - 1) < 1e-9);
        Assert.DoesNotContain(minors, m => m > Math.Pow(10, 3.1) || m < Math.Pow(10, -6.2));
        Assert.All(ticks.Where(t => !t.Major), t => Assert.Null(t.Label));
    }

    [Fact]
    public void ANarrowLogRangeIsLabelledWithinTheDecade()
    {
        var axis = new PlotAxis(AxisScale.Log10, (Math.Log10(1.5), Math.Log10(30)), 0, 400);
        var labels = AxisTicks.For(axis, 50, _ => true).Where(t => t.Label is not null).Select(t => t.Label).ToList();
        Assert.Equal(["2", "5", "10", "20"], labels);
    }
}
