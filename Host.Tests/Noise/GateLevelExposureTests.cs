using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Noise;

/// <summary>The gate-level oracle's noise exposure as the bridge counts it, and the table the analytic engine reads.</summary>
[Collection(QSharpCollection.Name)]
public class GateLevelExposureTests(FullStateFixture fixture)
{
    private BridgePool Pool => fixture.Engine.Pool;

    [Fact]
    public void ExposureCoversEveryLocationOfTheCircuitAndMeasurementsHarmOnlyByXAndY()
    {
        var expression = $"{QSharpOperations.MeasureGateGroverSearch}({GateEngine.OracleArgument(DeviceExperimentScene.Ray())}, 1)";
        System.Text.Json.Nodes.JsonObject summary = null!;
        Pool.ForEach([0], (_, bridge) => summary = bridge.Circuit(expression, exposure: true));
        var exposure = NoiseExposure.Parse(summary["exposure"]!);

        Assert.Equal(NoiseLocations.FromCircuit(summary["native"]!.AsObject()), exposure.Locations);
        // A Z before a computational-basis measurement changes nothing; an X flips the outcome.
        var measurements = Assert.Single(exposure.ByKind["M"]);
        Assert.Equal("XY", measurements.Key);
        // The oracle's CX gates load and compare data entangled with the index register: most of their locations are fully exposed.
        Assert.True(exposure.ByKind["CX"].GetValueOrDefault("XYZ") > 0.5 * exposure.LocationsOf("CX"));
    }

    [Fact]
    public void TheBuiltInTableHoldsWhatTheBenchTracesForItsShape()
    {
        var scene = SceneLoader.Load(Path.Combine(RepositoryPaths.Root, "Scenes", "qornell-8.json"));
        var table = GateLevelExposureTable.For(scene);
        Assert.NotNull(table);
        var traced = GateLevelExposure.Trace(Pool, GateLevelExposure.RepresentativeRay(scene), "test");
        // Z and CZ counts vary with the uncomputation's measured outcomes; everything else is fixed by the program.
        Assert.Equal(traced.Iteration.Locations, table.Iteration.Locations, 0.02 * traced.Iteration.Locations);
        // The graded harm reads the corrections a trace's measured outcomes left in it, and a table's per-iteration harm is the
        // difference of its r = 2 and r = 1 traces, so two traces' differ by up to a factor 2 (about 760 and 1,480 per iteration
        // at this shape): they are bounded, not matched. The table must be graded, as the bench grades shapes up to N = 16, and
        // grading only lowers what the ungraded count calls harmful.
        Assert.NotNull(table.Iteration.Harm);
        Assert.InRange(table.Iteration.HarmWeight, 0.25 * traced.Iteration.Ungraded.HarmWeight, 1.02 * traced.Iteration.Ungraded.HarmWeight);
        Assert.True(table.Outside.HarmWeight + table.Iteration.HarmWeight > 0, "a one-iteration run the table calls harmless");
        Assert.Equal(traced.Outside.Locations, table.Outside.Locations);
    }
}
