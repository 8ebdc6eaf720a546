using QuantumRayTracing.Cli;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Cli;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Noise;

/// <summary>
/// The device noise model (one-qubit and multi-qubit gate rates, readout error) on the searches: the analytic engine's
/// approximation against the lookup circuit evolved exactly, its sampling against the model, the gate-level oracle's harm
/// per gate kind, and what `render` does with it.
/// </summary>
public sealed class DeviceNoiseSearchTests : IDisposable
{
    // Rates far enough apart that a model taking the wrong rate for a gate, or no readout, misses by far more than the tolerance.
    private static readonly DeviceNoiseModel Device = new(2e-3, 3e-2, 0.05, 0.10);

    private static readonly Scene Qornell = SceneLoader.Load(Path.Combine(RepositoryPaths.Scenes, "qornell-64.json"));

    private readonly ScratchDirectory _scratch = new("qrt-device-");

    public void Dispose() => _scratch.Dispose();

    private static double Exact(DeviceNoiseModel device, int count, int marked, int iterations) =>
        LookupCircuitDensity.MarkedProbabilities(LookupSearchModel.TypicalSet(count, marked), iterations, CircuitRates.Of(device))[iterations];

    private static double Modelled(CircuitRates rates, int count, int marked, int iterations) =>
        DepolarizingApproximation.Default.NoisySuccess(rates)(count, marked, iterations);

    public static TheoryData<int, int, int> Rows => new() { { 8, 1, 1 }, { 8, 1, 2 }, { 8, 3, 1 }, { 16, 1, 3 }, { 16, 2, 2 } };

    [Theory]
    [MemberData(nameof(Rows))]
    public void TheLookupModelReadsMarkedIndicesAsTheEvolvedCircuitDoes(int count, int marked, int iterations)
    {
        // The evolution applies the readout to the circuit's exact distribution; the model to "ideal with Φ, else uniform". They
        // differ only by the shape of the noisy remainder, which the readout turns little: 0.005 is the stated tolerance (the
        // negative controls below miss by 0.05 and more).
        var (model, exact) = (Modelled(CircuitRates.Of(Device), count, marked, iterations), Exact(Device, count, marked, iterations));
        Assert.True(Math.Abs(model - exact) <= 0.005, $"N = {count}, t = {marked}, r = {iterations}: model {model:0.0000}, evolved {exact:0.0000}");
    }

    [Fact]
    public void ModelsWithoutTheReadoutOrWithOneRateForEveryGateAreRejected()
    {
        // Negative controls at the same tolerance: leaving the readout out, or running every gate at the two-qubit rate, must
        // miss the evolved circuit on some row.
        double WorstGap(CircuitRates rates) => Rows.Max(row =>
        {
            var (count, marked, iterations) = ((int)row[0], (int)row[1], (int)row[2]);
            return Math.Abs(Modelled(rates, count, marked, iterations) - Exact(Device, count, marked, iterations));
        });
        var twoQubitEverywhere = CircuitRates.Of(Device) with { OneQubit = NoiseModel.Depolarizing(Device.TwoQubit) };
        var (withoutReadout, oneRate) = (WorstGap(CircuitRates.Of(Device.WithoutReadout())), WorstGap(twoQubitEverywhere));
        Assert.True(withoutReadout > 0.05, $"the model without readout error fits the evolved circuit: worst gap {withoutReadout:0.0000}");
        Assert.True(oneRate > 0.05, $"the model with the two-qubit rate on every gate fits the evolved circuit: worst gap {oneRate:0.0000}");
    }

    [Fact]
    public void TheAnalyticEngineSamplesTheModelsReadout()
    {
        // 40,000 runs of N = 8, t = 1, r = 1: the marked share read must fit the model's P (false failure 1e-8) and reject the
        // same model without the readout error, which the engine applies by flipping each sampled index's bits.
        const int shots = 40_000;
        var request = new GroverRequest(LookupSearchModel.TypicalSet(8, 1), 1);
        var engine = new AnalyticEngine(new SeededRandom(3), device: Device);
        var read = engine.Measure(Enumerable.Repeat(request, shots).ToArray()).Count(i => i < 8 && request.Marked.Contains(i));
        StatisticalBounds.AssertBinomial(read, Modelled(CircuitRates.Of(Device), 8, 1, 1), shots, "analytic engine under the device model");
        var (low, high) = StatisticalBounds.BinomialInterval(Modelled(CircuitRates.Of(Device.WithoutReadout()), 8, 1, 1), shots);
        Assert.False(read >= low && read <= high, $"{read} marked reads also fit the model without readout error [{low}, {high}]");
    }

    [Fact]
    public void TheGateLevelHarmsEachGateKindAtItsArityRate()
    {
        // The gate-level oracle with its harms taken as independent: Φ = Π over parts, gate kinds and Paulis of (1 − p_kind/3)^h,
        // p the one-qubit rate for H, X, Z, the multi-qubit rate for CX, CZ, CCX and none for a measurement. Computed here from
        // the traced table directly.
        var traced = GateLevelExposureTable.For(Qornell)! with { Channels = null };
        const int iterations = 2;
        double Log(NoiseExposure part) => part.Harm!.Sum(kind =>
        {
            var p = kind.Key == "M" ? 0 : NoiseLocations.QubitsOf(kind.Key) >= 2 ? Device.TwoQubit : Device.OneQubit;
            return kind.Value.Values.Sum() * Math.Log(1 - p / 3);
        });
        var expected = Math.Exp(Log(traced.Outside) + iterations * Log(traced.Iteration));
        var rates = CircuitRates.Of(Device);
        Assert.Equal(expected, traced.RunFidelity(rates, 64, 1, iterations), 12);
        // A swapped classification would give the one-qubit rate to the CCX: a different Φ.
        var swapped = new CircuitRates(rates.TwoQubit, rates.OneQubit, NoiseModel.None);
        Assert.True(Math.Abs(traced.RunFidelity(swapped, 64, 1, iterations) - expected) > 0.01 * expected);
    }

    [Fact]
    public void ADeviceWithoutNoiseRendersAsTheIdealMachineAndANoisyOneBySeed()
    {
        var options = new RenderOptions(24, 24, Seed: 5);
        RgbImage Render(DeviceNoiseModel? device) =>
            Renderer.Render(Qornell, new EngineSetup(EngineKind.Analytic, new QSearchOptions(), Device: device), options).Image;
        var ideal = Render(null);
        Assert.True(Render(new DeviceNoiseModel(0, 0)).Pixels.SequenceEqual(ideal.Pixels));
        var noisy = Render(new DeviceNoiseModel(1e-3, 1e-2, 0.05));
        Assert.True(Render(new DeviceNoiseModel(1e-3, 1e-2, 0.05)).Pixels.SequenceEqual(noisy.Pixels));
        Assert.False(noisy.Pixels.SequenceEqual(ideal.Pixels));
    }

    [Theory]
    [InlineData("gate", "--device-noise", "1q=1e-3", ExitCodes.BadInput)]
    [InlineData("classical", "--readout-error", "0.01", ExitCodes.BadInput)]
    [InlineData("analytic", "--device-noise", "2q=2", ExitCodes.UsageError)]
    [InlineData("analytic", "--readout-error", "0.6,0.5", ExitCodes.UsageError)]
    public void RenderRefusesADeviceModelItCannotRunInOneLine(string engine, string option, string value, int exitCode)
    {
        var output = _scratch.File("x.png");
        var (code, error) = ConsoleCapture.Run(["render", Path.Combine(RepositoryPaths.Scenes, "qornell-8.json"), "-e", engine, "--size", "8", option, value, "-o", output]);
        Assert.Equal(exitCode, code);
        Assert.Contains(option, error);
        Assert.Single(error.Trim().Split('\n'));
        Assert.Empty(_scratch.FileNames());
    }

    [Fact]
    public void TheFullStateEngineRefusesADeviceModelOverNNotAPowerOfTwo()
    {
        var (code, error) = ConsoleCapture.Run(["search", "--count", "12", "--marked", "3", "-e", "fullstate", "--device-noise", "1q=1e-3"]);
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.Contains("N = 12", error);
        Assert.Single(error.Trim().Split('\n'));
    }

    [Fact]
    public void RenderRefusesPauliNoiseBesideADeviceModel()
    {
        var (code, error) = ConsoleCapture.Run(["render", Path.Combine(RepositoryPaths.Scenes, "qornell-8.json"), "--size", "8", "--noise", "1e-3", "--device-noise", "1q=1e-3", "-o", _scratch.File("x.png")]);
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.Contains("give one noise model", error);
        Assert.Empty(_scratch.FileNames());
    }
}
