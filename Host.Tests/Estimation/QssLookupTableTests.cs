using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Estimation;

public class QssLookupTableTests
{
    [Theory]
    [InlineData(16, 4)]
    [InlineData(5, 3)]
    [InlineData(64, 7)]
    [InlineData(1, 1)]
    public void ColumnsAreProbabilityDistributions(int subpixels, int counterBits)
    {
        var table = QssLookupTable.Exact(subpixels, counterBits);
        for (var h = 0; h <= subpixels; h++)
        {
            var total = 0.0;
            for (var y = 0; y < table.Readouts; y++)
            {
                Assert.InRange(table.Probabilities[y, h], 0, 1);
                total += table.Probabilities[y, h];
            }
            Assert.Equal(1, total, 1e-9);
        }
        Assert.All(table.ConfidenceOfReadout, c => Assert.InRange(c, 0, 1));
    }

    [Fact]
    public void ExactTableMatchesTheDirectSum()
    {
        var table = QssLookupTable.Exact(16, 4);
        for (var h = 0; h <= 16; h++)
        {
            var direct = FullStateCoinEngineTests.ExactReadout(h / 16.0, 4);
            for (var y = 0; y < 16; y++) Assert.Equal(direct[y], table.Probabilities[y, h], 1e-12);
        }
    }

    [Fact]
    public void FourCounterBitsAndSixteenSubpixelsReachTheThesisAccuracy()
    {
        // The thesis's setting (4 counter qubits, 16 subpixels; docs/conventions.md, Sources): about 0.92 hits mean error,
        // about 49% exact, over hit counts 0..16 equally likely.
        var table = QssLookupTable.Exact(16, 4);
        var (error, exact) = (0.0, 0.0);
        for (var h = 0; h <= 16; h++)
            for (var y = 0; y < 16; y++)
            {
                error += table.Probabilities[y, h] * Math.Abs(table.HitsOfReadout[y] - h) / 17;
                if (table.HitsOfReadout[y] == h) exact += table.Probabilities[y, h] / 17;
            }
        Assert.InRange(error, 0.92 * 0.95, 0.92 * 1.05);
        Assert.InRange(exact, 0.44, 0.54);
    }

    [Theory]
    [InlineData(5)]
    [InlineData(0)]
    [InlineData(16)]
    public void TileWithKnownHitCountIsReadWithTheTablesProbability(int hits)
    {
        var table = QssLookupTable.Exact(16, 4);
        const int shots = 20000;
        var tile = Enumerable.Range(0, 16).Select(i => i < hits ? 1.0 : 0.0).ToArray();
        var readouts = new AnalyticCoinEngine(new SeededRandom(31)).ReadCounters([new QssRequest(tile, 4, shots)])[0];
        var correct = readouts.Count(y => table.HitsOfReadout[y] == hits);
        var p = Enumerable.Range(0, 16).Where(y => table.HitsOfReadout[y] == hits).Sum(y => table.Probabilities[y, hits]);
        StatisticalBounds.AssertBinomial(correct, Math.Min(1, p), shots, $"h = {hits}");
    }

    [Fact]
    public void ConfidenceIsRowMaxOverRowTotal()
    {
        var p = new double[2, 3] { { 0.7, 0.2, 0.1 }, { 0.3, 0.8, 0.9 } };
        var table = new QssLookupTable(2, 1, p, "test");
        Assert.Equal([0, 2], table.HitsOfReadout);
        Assert.Equal(0.7, table.ConfidenceOfReadout[0], 1e-12);
        Assert.Equal(0.9 / 2.0, table.ConfidenceOfReadout[1], 1e-12);
    }
}
