using System.Globalization;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Noise;

/// <summary>
/// The supersampling noise model against the noisy full-state simulator, which cannot be seeded: each comparison allows
/// the model's tolerance δ = <see cref="NoiseReport.ModelTolerance"/> plus z = 4.89 binomial standard errors
/// (false-failure at most 1e-6 per comparison, below 3e-5 per test).
/// </summary>
[Collection(QSharpCollection.Name)]
public class NoisySupersamplingSimulatorTests(FullStateFixture fixture)
{
    private static readonly NoiseModel[] Levels = [NoiseModel.Depolarizing(1e-3), NoiseModel.Depolarizing(3e-3), NoiseModel.Depolarizing(1e-2)];

    // Mean 0.0955 = sin²(π/10): after two Grover operators a head is certain, as far from the ½ noise pulls to as a coin gets.
    private static readonly double[] Mean = CoinValues.MeanCoin([0.05, 0.2, 0.1, 0.032]);

    private static readonly double[] Shifted = CoinValues.Shifted([0.3, 0.5, 0.2, 0.6], 0.2);

    private BridgePool Pool => fixture.Engine.Pool;

    private long Traced(string expression)
    {
        long locations = 0;
        Pool.ForEach([expression], (e, bridge) => locations = NoiseLocations.FromCircuit(bridge.Circuit(e)["native"]!.AsObject()));
        return locations;
    }

    private static string Doubles(IEnumerable<double> values) =>
        "[" + string.Join(", ", values.Select(v => v.ToString("0.0###############", CultureInfo.InvariantCulture))) + "]";

    public static TheoryData<string, double[], int> CoinShapes => new()
    {
        { "mean", [0.5], 0 },
        { "mean", [0.5], 2 },
        { "mean", [0.5, 0.3], 1 },
        { "mean", [0.5, 0.0, 0.2, 0.1], 2 },
        { "mean", [0.5, 0.3, 0.2, 0.1, 0.5, 0.0, 0.2, 1.0], 1 },
        { "mean", [.. Enumerable.Range(0, 16).Select(i => i % 3 == 0 ? 0.0 : 0.4)], 1 },
        // N not a power of two: the uniform preparation's recursion, down to a doubly controlled H at N = 7.
        { "mean", [0.5, 0.3, 0.0], 1 },
        { "mean", [0.5, 0.3, 0.2, 0.1, 0.5, 0.3, 0.2], 0 },
        { "shifted", [0.5, 0.3, 0.2, 0.1, -0.5], 1 },
        { "shifted", [0.5, -0.3], 1 },
        { "shifted", [0.5, 0.3, -0.2, 0.1], 2 },
        { "shifted", [0.5, 0.3, 0.2, 0.0, 0.5, 0.3, 0.2, 0.1], 1 },
        { "direct", [0.3], 0 },
        { "direct", [0.3], 5 },
    };

    [Theory]
    [MemberData(nameof(CoinShapes))]
    public void CoinNoiseLocationsMatchTheExtractedCircuit(string kind, double[] amplitudes, int iterations)
    {
        // One flip of the coin as the fullstate engine runs it; resets are not locations, measurements are.
        var coin = Enum.Parse<CoinKind>(kind, ignoreCase: true);
        var expression = coin == CoinKind.Direct
            ? $"QuantumRayTracing.Supersampling.CountDirectCoinHeads({Doubles(amplitudes)[1..^1]}, {iterations}, 1)"
            : $"QuantumRayTracing.Supersampling.CountCoinHeads({(coin == CoinKind.Shifted ? "true" : "false")}, {Doubles(amplitudes)}, {iterations}, 1)";
        Assert.Equal(Traced(expression), CoinNoiseLocations.Flip(coin, amplitudes, iterations));
    }

    [Theory]
    [InlineData(new[] { 0.5 }, 1)]
    [InlineData(new[] { 0.5 }, 3)]
    [InlineData(new[] { 0.5, 0.3 }, 2)]
    [InlineData(new[] { 0.5, 0.3, 0.0, 1.0 }, 3)]
    [InlineData(new[] { 0.5, 0.3, 0.2, 0.1, 0.5, 0.3, 0.0, 0.1 }, 2)]
    [InlineData(new[] { 0.5, 0.0, 0.2 }, 2)]
    [InlineData(new[] { 0.5, 0.3, 0.2, 0.1, 0.5, 0.3, 0.2 }, 1)]
    [InlineData(new[] { 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0, 1.0 }, 2)]
    public void QssNoiseLocationsMatchTheExtractedCircuit(double[] amplitudes, int counterBits) =>
        Assert.Equal(Traced($"QuantumRayTracing.Supersampling.MeasureQssReadout({Doubles(amplitudes)}, {counterBits})"), CoinNoiseLocations.Qss(amplitudes, counterBits));

    [Theory]
    [InlineData(3)]
    [InlineData(7)]
    [InlineData(12)]
    [InlineData(15)]
    [InlineData(16)]
    public void UniformPreparationLocationsMatchTheExtractedCircuit(int count)
    {
        // MeasureGroverSearch with r = 0 and nothing marked is the preparation and the measurement of the index register.
        var width = CoinRegisters.SubpixelQubits(count);
        Assert.Equal(Traced($"QuantumRayTracing.Search.MeasureGroverSearch({count}, [0, size = 0], 0)"), CoinNoiseLocations.UniformPreparation(count, width, 0) + width);
    }

    [Fact]
    public void DirectCoinModelIsExact()
    {
        // One qubit: each noise location is the depolarizing channel ρ → (1 − 4p/3)ρ + (4p/3)I/2 exactly, so the model
        // needs no tolerance δ: 4000 flips each, within z = 4.89 standard errors (false-failure 1e-6 per comparison).
        double[] coin = [Math.Sqrt(0.1)];
        SupersamplingCheckCase[] cases = [SupersamplingCheckCase.Coin(CoinKind.Direct, coin, 4), SupersamplingCheckCase.Coin(CoinKind.Direct, coin, 16)];
        var rows = SupersamplingNoiseCheck.Measure(Pool, cases, [NoiseModel.Depolarizing(3e-3), NoiseModel.Depolarizing(1e-2)], shots: 4000);
        var model = DepolarizingApproximation.Default;
        foreach (var row in rows)
            Assert.True(Math.Abs(row.Observed - row.Predicted(model)) <= NoiseCheck.Z * row.StandardError(model),
                $"direct coin, m = {row.Case.Iterations}, {row.Noise}: observed {row.Observed:0.0000}, model {row.Predicted(model):0.0000}");
        // The multi-qubit coins' s = 2/3 would undercount a lone qubit's harm: at m = 16 and p = 1e-2 it is rejected.
        var strong = rows.Single(r => r.Case.Iterations == 16 && r.Noise.PerGate == 1e-2);
        var phi = model.Fidelity(strong.Noise, strong.Case.Locations);
        var twoThirds = phi * strong.Ideal + (1 - phi) / 2;
        Assert.True(Math.Abs(strong.Observed - twoThirds) > NoiseCheck.Z * strong.StandardError(model), $"observed {strong.Observed:0.0000} fits s = 2/3's {twoThirds:0.0000}");
    }

    [Fact]
    public void ApproximationAgreesWithTheNoisySimulator()
    {
        // The mean and the shifted (QCoin) coin over 4 subpixels at m = 0, 1, 2, the direct coin at m = 4, and a QSS readout
        // with 3 counter bits, at three error rates; 300 runs each (σ ≤ 0.029, an acceptance region of at most ±0.20, each still
        // failing falsely with probability at most 1e-6). At 300 runs the same rows as at 500 tell the model from the ideal formula
        // (the mean coin and the shifted one at m = 2 and 1e-2, the QSS readout at every rate), and the ½ share below lies 7.5σ
        // beyond its bound.
        SupersamplingCheckCase[] cases =
        [
            .. Enumerable.Range(0, 3).Select(m => SupersamplingCheckCase.Coin(CoinKind.Mean, Mean, m)),
            .. Enumerable.Range(0, 3).Select(m => SupersamplingCheckCase.Coin(CoinKind.Shifted, Shifted, m)),
            SupersamplingCheckCase.Coin(CoinKind.Direct, [Math.Sqrt(0.1)], 16),
            SupersamplingCheckCase.Qss(Mean, 3),
        ];
        var rows = SupersamplingNoiseCheck.Measure(Pool, cases, Levels, shots: 300);
        Assert.Equal(cases.Length * Levels.Length, rows.Count);
        var model = DepolarizingApproximation.Default;
        double Bound(SupersamplingCheckRow row) => NoiseReport.ModelTolerance + NoiseCheck.Z * row.StandardError(model);
        foreach (var row in rows)
            Assert.True(Math.Abs(row.Observed - row.Predicted(model)) <= Bound(row),
                $"{row.Case.Shape}, m = {row.Case.Iterations}, t = {row.Case.CounterBits}, {row.Noise}: observed {row.Observed:0.000}, model {row.Predicted(model):0.000}, allowed ±{Bound(row):0.000}");

        // The model is not vacuous: wherever it parts from the ideal probability by more than twice the acceptance
        // bound, the simulator rejects the ideal formula (the QSS readout at every rate, the amplified coins at 1e-2).
        var telling = rows.Where(r => Math.Abs(r.Predicted(model) - r.Ideal) > 2 * Bound(r)).ToArray();
        Assert.Contains(telling, r => r.Case.IsQss);
        Assert.Contains(telling, r => r.Case.Kind == CoinKind.Shifted);
        Assert.Contains(telling, r => r.Case.Kind == CoinKind.Mean);
        foreach (var row in telling)
            Assert.True(Math.Abs(row.Observed - row.Ideal) > Bound(row), $"{row.Case.Shape}, {row.Noise}: the ideal probability {row.Ideal:0.000} fits {row.Observed:0.000}");

        // The shifted coin's noise share is 1/2^(n+1), not the ½ of a single-qubit coin: at 1e-2 and m = 2 the model with ½ is rejected.
        var shifted = rows.Single(r => r.Case.Kind == CoinKind.Shifted && r.Case.Iterations == 2 && r.Noise.PerGate == 1e-2);
        var phi = SupersamplingNoise.CoinFidelity(CoinKind.Shifted, Shifted, 2, shifted.Noise);
        var withHalf = phi * shifted.Ideal + (1 - phi) / 2;
        Assert.True(Math.Abs(shifted.Observed - withHalf) > Bound(shifted), $"observed {shifted.Observed:0.000} fits the ½ share's {withHalf:0.000}");
    }
}
