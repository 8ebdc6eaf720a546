namespace QuantumRayTracing.Estimation;

/// <summary>Run the QSS circuit <see cref="Shots"/> times on one tile; the engine returns each counter readout.</summary>
/// <param name="Amplitudes">√F(i) per subpixel; for the direct coin its one head amplitude √f.</param>
/// <param name="CounterBits">t: the readout lies in 0..2^t − 1.</param>
/// <param name="Shots">Independent runs.</param>
/// <param name="Coin"><see cref="CoinKind.Mean"/> (the subpixel register and the shader oracle) or <see cref="CoinKind.Direct"/> (the QCoin paper's device QSS: one coin qubit).</param>
public sealed record QssRequest(double[] Amplitudes, int CounterBits, int Shots, CoinKind Coin = CoinKind.Mean)
{
    /// <summary>Queries of one run: the preparation and 2^t − 1 Grover operators at two queries each.</summary>
    public static long QueriesPerRun(int counterBits) => (2L << counterBits) - 1;
}
