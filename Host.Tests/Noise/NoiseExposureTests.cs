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
        Assert.Equal(run.Run(3).Fidelity(noise), run.RunFidelity(noise, 3), 12);
        Assert.Equal(run.Outside.Fidelity(noise), run.RunFidelity(noise, 0), 12);
    }
}
