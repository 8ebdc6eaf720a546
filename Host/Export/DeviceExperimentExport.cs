using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Export;

/// <summary>
/// The ray tracing paper's device experiment (sec. 8, fig. 15) as an export: the scene and ray `bench noise`
/// runs (<see cref="DeviceExperimentScene"/>), one Grover iteration (the optimum at N = 4 with one marked),
/// with the narrow oracle, which marks the same primitive as the compact one the bench simulates.
/// </summary>
public static class DeviceExperimentExport
{
    public const int Iterations = 1;

    public static ExportSubject Subject()
    {
        var input = DeviceExperimentScene.Ray() with { Construction = OracleConstruction.Narrow };
        return SearchExport.Subject("qrt export device-experiment", DeviceExperimentScene.Build().Name, $"the device experiment's ray (the first camera ray of {DeviceExperimentScene.ImageSize}x{DeviceExperimentScene.ImageSize} that meets exactly one primitive)", input, Iterations);
    }
}
