namespace QuantumRayTracing.Estimation;

/// <summary>
/// The qubits the supersampling circuits allocate, as the Q# sources do (<c>SubpixelQubits</c>): ceil(log2 N)
/// subpixel qubits and one coin qubit (the direct coin: the coin qubit alone); a QSS readout adds its counter. Every one of them can be superposed.
/// </summary>
public static class CoinRegisters
{
    public static int SubpixelQubits(int subpixels) => subpixels <= 1 ? 0 : 32 - int.LeadingZeroCount(subpixels - 1);

    /// <summary>A coin circuit: the subpixel register and the coin.</summary>
    public static int Coin(int subpixels) => SubpixelQubits(subpixels) + 1;

    /// <summary>A coin circuit of <paramref name="kind"/>: the direct coin is its one qubit.</summary>
    public static int Coin(CoinKind kind, int subpixels) => kind == CoinKind.Direct ? 1 : Coin(subpixels);

    /// <summary>A QSS readout: the counter, the subpixel register and the coin.</summary>
    public static int Qss(int subpixels, int counterBits) => counterBits + Coin(subpixels);
}
