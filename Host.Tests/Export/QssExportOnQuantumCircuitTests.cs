using System.Globalization;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// `qrt export qss --format qasm2` on quantum-circuit (npm, not ours): the counter's distribution it computes
/// from the file's gates, summed over the unmeasured coin register, must equal the header's, which the QDK
/// computed from its own state vector (exact on both sides: tolerance 1e-9). The header must also equal the
/// closed-form readout distribution the analytic engine samples QSS from (<see cref="CoinProbability.QssReadout"/>),
/// so the exported circuit is the QSS the renderer counts with. Dropping the H of counter bit 0, or running the
/// circuit of another mean, must fail the comparison.
/// </summary>
public sealed class QssExportOnQuantumCircuitTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-export-qss-");

    public void Dispose() => _scratch.Dispose();

    /// <summary>The file `qrt export qss` writes (<see cref="ExportCache"/>: made once per test run).</summary>
    private static string Export(double[] values, int counterBits) =>
        ExportCache.File(["export", "qss", "--values", .. values.Select(v => v.ToString(CultureInfo.InvariantCulture)), "--counter-bits", counterBits.ToString(CultureInfo.InvariantCulture)]);

    [Theory]
    [InlineData(2, 0.25, 0.6)] // mean 0.425: θ/π is off the grid, the readout spreads over all four values
    [InlineData(3, 0.0, 1.0, 1.0, 1.0)] // binary subpixels, mean 0.75: θ/π = 1/3
    [InlineData(3, 0.05, 0.2, 0.1, 0.032, 0.5)] // N = 5, not a power of two: the preparation has rotations
    public void CounterDistributionOnQuantumCircuitIsTheHeadersAndTheAnalyticEngines(int counterBits, params double[] values)
    {
        var file = Export(values, counterBits);
        var ideal = ExportedDistribution.FromHeader(file);
        var simulated = ExportedDistribution.OnQuantumCircuit(file, "counter");
        ExportedDistribution.AssertAgree(ideal, simulated, "header", "quantum-circuit");
        // jsqubits reads the same gates (rz, ry, controlled rotations' decompositions) alike.
        var sparse = ExportedDistribution.OnJsqubits(file, "counter");
        ExportedDistribution.AssertAgree(simulated, sparse, "quantum-circuit", "jsqubits");
        var analytic = CoinProbability.QssReadout(values.Average(), counterBits).Select((p, y) => (y, p)).ToDictionary(e => e.y, e => e.p);
        ExportedDistribution.AssertAgree(ideal, analytic, "header", "closed form");
        // Not a flat distribution: the readout concentrates (uniform would be 1/2^t everywhere).
        Assert.True(ideal.Values.Max() > 1.5 / (1 << counterBits), $"no peak in {string.Join(' ', ideal)}");
    }

    [Fact]
    public void DroppedCounterHadamardIsRejected()
    {
        var file = Export([0.0, 1.0, 1.0, 1.0], 3);
        var difference = ExportedDistribution.HeaderDifferenceWithout(file, l => l == "h q[0];", "counter", _scratch.File("broken.qasm"));
        Assert.True(difference > 1e-2, $"dropping the H of counter bit 0 changed the distribution by only {difference}");
    }

    [Fact]
    public void CircuitOfAnotherMeanIsRejected()
    {
        // One subpixel of four switched off: mean 0.5 instead of 0.75, compared with the 0.75 file's header.
        var promised = ExportedDistribution.FromHeader(Export([0.0, 1.0, 1.0, 1.0], 3));
        var other = ExportedDistribution.OnQuantumCircuit(Export([0.0, 1.0, 1.0, 0.0], 3), "counter");
        var difference = ExportedDistribution.MaxDifference(promised, other);
        Assert.True(difference > 1e-2, $"the mean-0.5 circuit differs from the mean-0.75 header by only {difference}");
    }
}
