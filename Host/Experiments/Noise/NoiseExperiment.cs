using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench noise`: the parts the settings ask for measured (<see cref="NoiseBenchmark"/>) and reported
/// (<see cref="NoiseReport"/>, docs/noise.md), with the machine they ran on for the report's footer.
/// </summary>
public static class NoiseExperiment
{
    /// <param name="settings">The parts and their sizes; the cluster's bridges when the simulator work runs there.</param>
    /// <param name="progress">A line per step, as it starts.</param>
    public static (Report Report, string Machine, IReadOnlyList<(string Key, string Scenes, Noise.GateLevelExposure Exposure)> Exposures) Run(NoiseBenchSettings settings, Action<string> progress)
    {
        var result = NoiseBenchmark.Run(settings, progress);
        return (NoiseReport.Of(result, settings), result.Machine, result.Exposures);
    }
}
