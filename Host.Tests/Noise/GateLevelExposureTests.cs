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

    /// <summary>
    /// One two-iteration trace's per-iteration harm weight at qornell-8's shape spreads with standard deviation 13.4 about the mean
    /// (818; 12 traces before the table was built, and the table's own 8 in docs/noise.md); 21 is the 95 % upper confidence bound
    /// of that deviation over the 12 (χ² with 11 degrees of freedom).
    /// </summary>
    private const double TraceSpreadAtEight = 21;

    /// <summary>Two-sided z at false-failure 1e-6.</summary>
    private const double Z = 4.89;

    [Fact]
    public void EveryTableEntryIsGradedWithNonnegativeHarmAndAMeasuredSpread()
    {
        foreach (var key in GateLevelExposureTable.Keys)
        {
            var entry = GateLevelExposureTable.Entries[key];
            Assert.NotNull(entry.Estimate);
            Assert.True(entry.Estimate.Traces >= 2, $"{key}: {entry.Estimate.Traces} traces give no spread");
            Assert.True(entry.Estimate.IterationSpread > 0, $"{key}: spread {entry.Estimate.IterationSpread}");
            foreach (var part in new[] { entry.Outside, entry.Iteration })
            {
                Assert.NotNull(part.Harm);
                Assert.All(part.Harm.Values.SelectMany(p => p.Values), h => Assert.True(h >= 0, $"{key}: harm {h}"));
            }
            // Grading only lowers what the counting rule calls harmful, and an iteration of a search is never harmless.
            Assert.InRange(entry.Iteration.HarmWeight, 0.1 * entry.Iteration.Ungraded.HarmWeight, 1.02 * entry.Iteration.Ungraded.HarmWeight);
            Assert.True(entry.Outside.HarmWeight > 0, $"{key}: a measured index register the table calls unharmed by X errors");
            // Every shape is traced with two iterations (N = 8 and up, one marked, optimum 2 or more): an inner and a last iteration.
            Assert.NotNull(entry.Channels?.Inner);
            Assert.True(entry.Channels.Last.Cross.Depolarizing > 0 && entry.Channels.Inner.Full.Depolarizing > 0, $"{key}: an iteration without dephasing or whole harms");
        }
    }

    [Fact]
    public void TheTracedRunStopsAtTheRaysOptimalIterationCount()
    {
        // N = 4 with one marked: θ = 30°, one iteration reads it with certainty and a second leaves P(marked) = sin²(150°) = 1/4,
        // the uniform readout, where the grading's h has nothing to divide by. N = 8 with one marked: θ ≈ 20.7°, optimum 2.
        var device = DeviceExperimentScene.Ray();
        Assert.Equal((4, 1), (device.Table.Count, device.Table.Marked(device.Window).MarkedCount));
        Assert.Equal(1, GateLevelExposure.TracedIterations(device));
        var eight = NoiseBenchmark.EightPrimitiveRay();
        Assert.Equal((8, 1), (eight.Table.Count, eight.Table.Marked(eight.Window).MarkedCount));
        Assert.Equal(GateLevelExposure.MaxTracedIterations, GateLevelExposure.TracedIterations(eight));
    }

    [Fact]
    public void TheChannelsAgreeWithTheGradedHarmToFirstOrderAtTheTracedCount()
    {
        // Both come from one grading of each error, by two routes: the harm h simulates the index register with that error alone;
        // the channels average each error's dephasing over pairs of index values and the run simulates their sum. At p = 1e-7 the
        // run's 1 − Φ is its first-order harm to within 1e-4 of itself. At the traced count (r = 2 here) they differ only where the
        // grading counts a helpful error as no harm (the channels keep its help) and where the two oracle sections' dephasing
        // differs (the channels average them): 3 % on the traces measured, so 6 % is allowed; a channel dropped, doubled or put
        // in the wrong class misses by far more. At r = 1 the channels must cost more than the equal share per iteration: a sign
        // flip in the only oracle section harms as in the first of two, more than one in the last of two (1 against 0.6 of a
        // uniformly dephased register's harm at N = 8), which the equal split gives every section alike (986 against 831 measured).
        // The ray's traced exposure (three graded traces) is the one the model checks of NoisySimulatorTests read: traced once per run.
        var eight = NoiseBenchmark.EightPrimitiveRay();
        var traced = NoiseCheck.Exposure(Pool, eight);
        Assert.NotNull(traced.Channels);
        const double p = 1e-7;
        var noise = NoiseModel.Depolarizing(p);
        var marked = eight.Table.Marked(eight.Window).MarkedCount;
        // Whole-harm errors at a whole harm, as the grading counts them (the model's fitted share is not the grading's).
        double Harm(int r) => (1 - traced.RunFidelity(noise, eight.Table.Count, marked, r, wholeHarm: 1)) / p;
        var atTraced = Harm(GateLevelExposure.MaxTracedIterations);
        var graded = traced.Run(GateLevelExposure.MaxTracedIterations).HarmWeight;
        Assert.True(Math.Abs(atTraced - graded) <= 0.06 * graded, $"r = 2: channels' first-order harm {atTraced:0.0}, graded {graded:0.0}");
        Assert.True(Harm(1) > 1.1 * traced.Run(1).HarmWeight, $"r = 1: channels' first-order harm {Harm(1):0.0}, equal share {traced.Run(1).HarmWeight:0.0}");
    }

    [Fact]
    public void ATableWithANegativeHarmIsRefused()
    {
        var table = System.Text.Json.Nodes.JsonNode.Parse(File.ReadAllText(Path.Combine(RepositoryPaths.Root, "Host", "Noise", "gate-level-exposure.json")))!;
        var key = GateLevelExposureTable.Keys.First();
        var harm = table[key]!["iterationHarm"]!.AsObject().First();
        harm.Value!["X"] = -1.0;
        var error = Assert.Throws<InvalidDataException>(() => GateLevelExposureTable.Parse(table));
        Assert.Contains($"iterationHarm.{harm.Key}.X", error.Message);
    }

    [Fact]
    public void ATableWithANegativeDecayWeightIsRefused()
    {
        var table = System.Text.Json.Nodes.JsonNode.Parse(File.ReadAllText(Path.Combine(RepositoryPaths.Root, "Host", "Noise", "gate-level-exposure.json")))!;
        var key = GateLevelExposureTable.Keys.First();
        table[key]!["channels"]!["last"]!["cross"]!["Z"] = -1.0;
        var error = Assert.Throws<InvalidDataException>(() => GateLevelExposureTable.Parse(table));
        Assert.Contains("channels.last.cross.Z", error.Message);
    }

    [Fact]
    public void TheBuiltInTableAgreesWithAFreshEstimateWithinItsSpread()
    {
        // The table's per-iteration harm (the mean of K traces) against a fresh mean of three (the traces the model checks read; the
        // representative ray is the 8-primitive ray they use, so the trace is shared): their difference has standard deviation
        // σ·√(1/K + 1/2) with σ the spread of one trace; allowed z times that with σ at its upper confidence bound, so a false
        // failure has probability below 1e-6 (about 1e-3 were σ half as large again as that bound). The old estimator (the
        // difference of a two- and a one-iteration trace) moved by 380 to 700 between traces at this shape, far outside.
        var scene = SceneLoader.Load(Path.Combine(RepositoryPaths.Root, "Scenes", "qornell-8.json"));
        var table = GateLevelExposureTable.For(scene);
        Assert.NotNull(table?.Estimate);
        var fresh = NoiseCheck.Exposure(Pool, GateLevelExposure.RepresentativeRay(scene));
        Assert.Equal(GateLevelExposure.DefaultTraces, fresh.Estimate!.Traces);
        var tolerance = Z * TraceSpreadAtEight * Math.Sqrt(1.0 / table.Estimate.Traces + 1.0 / fresh.Estimate!.Traces);
        Assert.True(Math.Abs(fresh.Iteration.HarmWeight - table.Iteration.HarmWeight) <= tolerance,
            $"per-iteration harm weight: table {table.Iteration.HarmWeight:0.0}, fresh {fresh.Iteration.HarmWeight:0.0}, allowed ±{tolerance:0.0}");
        // The fresh traces' own spread lies within what the stated spread allows: their sample deviation s has 2s²/σ² ~ χ² with two
        // degrees of freedom, above zσ with probability exp(−z²) = 4e-11.
        Assert.InRange(fresh.Estimate.IterationSpread, 0, Z * TraceSpreadAtEight);
        // The outside is graded whole on every trace: the same preparation and measurement, the same harm.
        Assert.Equal(table.Outside.HarmWeight, fresh.Outside.HarmWeight, 3);
        Assert.Equal(table.Outside.Locations, fresh.Outside.Locations);
        // Z and CZ counts vary with the uncomputation's measured outcomes; everything else is fixed by the program.
        Assert.Equal(fresh.Iteration.Locations, table.Iteration.Locations, 0.02 * fresh.Iteration.Locations);
    }
}
