using QuantumRayTracing.Noise;

namespace QuantumRayTracing.Tests.Noise;

public class NoiseExposureTests
{
    private static NoiseExposure Of(params (string Kind, string Pattern, double Count)[] entries) =>
        new(entries.GroupBy(e => e.Kind).ToDictionary(g => g.Key, g => (IReadOnlyDictionary<string, double>)g.ToDictionary(e => e.Pattern, e => e.Count)));

    [Fact]
    public void FidelityMultipliesTheHarmfulProbabilityOfEveryLocation()
    {
        // 10 locations where X, Y and Z harm, 20 where only X and Y do, 5 where none does, at px = py = pz = 0.01:
        // Φ = (1 − 0.03)^10 · (1 − 0.02)^20.
        var exposure = Of(("CX", "XYZ", 10), ("M", "XY", 20), ("X", "", 5));
        Assert.Equal(Math.Pow(0.97, 10) * Math.Pow(0.98, 20), exposure.Fidelity(NoiseModel.Depolarizing(0.03)), 12);
        Assert.Equal(35, exposure.Locations);
        Assert.Equal(10 + 20 * 2.0 / 3, exposure.HarmWeight, 12);
        // Pure Z noise harms only where Z does: (1 − 0.01)^10.
        Assert.Equal(Math.Pow(0.99, 10), exposure.Fidelity(new NoiseModel(0, 0, 0.01)), 12);
        Assert.Equal(1.0, exposure.Fidelity(NoiseModel.None));
    }

    [Fact]
    public void RunsAddTheIterationsToThePreparation()
    {
        var run = new GateLevelExposure("test", Of(("H", "XYZ", 3)), Of(("CX", "XYZ", 100), ("M", "XY", 6)));
        var noise = NoiseModel.Depolarizing(3e-3);
        Assert.Equal(3 + 3 * 106, run.Run(3).Locations, 12);
        Assert.Equal(run.Run(3).Fidelity(noise), run.IndependentHarmsFidelity(noise, 3), 12);
        Assert.Equal(run.Outside.Fidelity(noise), run.IndependentHarmsFidelity(noise, 0), 12);
    }

    [Fact]
    public void GradedHarmReplacesThePatternsAndAWholeHarmGivesThePatternsFactor()
    {
        var patterns = Of(("CX", "XYZ", 10), ("M", "XY", 20));
        // The same locations graded, every harmful Pauli a whole harm: each Pauli its own factor (1 − p_P), the patterns'
        // (1 − Σ p_P) to first order.
        Dictionary<string, IReadOnlyDictionary<string, double>> whole = new()
        {
            ["CX"] = new Dictionary<string, double> { ["X"] = 10, ["Y"] = 10, ["Z"] = 10 },
            ["M"] = new Dictionary<string, double> { ["X"] = 20, ["Y"] = 20, ["Z"] = 0 },
        };
        var noise = new NoiseModel(0.01, 0.02, 0.005);
        Assert.Equal(Math.Pow(0.99, 30) * Math.Pow(0.98, 30) * Math.Pow(0.995, 10), (patterns with { Harm = whole }).Fidelity(noise), 12);
        Assert.Equal(patterns.Fidelity(noise), (patterns with { Harm = whole }).Fidelity(noise), 2);
        // Half the harm: Φ^(1/2) per Pauli; a third of the summed harm is the harm weight.
        var half = whole.ToDictionary(k => k.Key, k => (IReadOnlyDictionary<string, double>)k.Value.ToDictionary(p => p.Key, p => p.Value / 2));
        var graded = patterns with { Harm = half };
        Assert.Equal(Math.Pow(0.99, 15) * Math.Pow(0.98, 15) * Math.Pow(0.995, 5), graded.Fidelity(noise), 12);
        Assert.Equal((15 + 15 + 5) / 3.0, graded.HarmWeight, 12);
        Assert.Equal(patterns.Fidelity(noise), graded.Ungraded.Fidelity(noise), 12);
        // Sums and differences keep the grading only where both sides have it.
        Assert.Equal(2 * graded.HarmWeight, (graded + graded).HarmWeight, 12);
        Assert.Null((graded + patterns).Harm);
    }
}
