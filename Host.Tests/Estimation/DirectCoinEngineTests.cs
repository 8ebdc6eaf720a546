using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Tests.Estimation;

public class DirectCoinEngineTests
{
    /// <summary>Keeps what it is asked to flip, and answers no heads.</summary>
    private sealed class Recording : ICoinEngine
    {
        public List<CoinRequest> Requests { get; } = [];

        public string Name => "recording";

        public IReadOnlyList<int> FlipCoins(IReadOnlyList<CoinRequest> requests)
        {
            Requests.AddRange(requests);
            return new int[requests.Count];
        }

        public IReadOnlyList<int[]> ReadCounters(IReadOnlyList<QssRequest> requests) => [.. requests.Select(r => new int[r.Shots])];

        public IReadOnlyList<int> CountAncillaZeros(IReadOnlyList<AncillaPhaseRequest> requests) => new int[requests.Count];

        public void Dispose() { }
    }

    [Fact]
    public void EveryCoinBecomesADirectCoinOfTheSameHeadAmplitude()
    {
        CoinRequest[] requests =
        [
            new(CoinKind.Mean, [0.1, 0.5, 0.9, 1.0], 0, 7),
            new(CoinKind.Mean, [0.3], 3, 2),
            new(CoinKind.Shifted, [0.2, -0.1, 0.4, 0.3], 2, 5),
            new(CoinKind.Shifted, [-0.6, -0.2], 1, 1),
        ];
        var inner = new Recording();
        new DirectCoinEngine(inner).FlipCoins(requests);
        Assert.Equal(requests.Length, inner.Requests.Count);
        for (var k = 0; k < requests.Length; k++)
        {
            var (original, forwarded) = (requests[k], inner.Requests[k]);
            Assert.Equal(CoinKind.Direct, forwarded.Kind);
            Assert.Equal((original.Iterations, original.Flips), (forwarded.Iterations, forwarded.Flips));
            Assert.Equal(CoinProbability.HeadAmplitude(original.Kind, original.Amplitudes), CoinProbability.HeadAmplitude(CoinKind.Direct, forwarded.Amplitudes), 12);
        }
    }
}
