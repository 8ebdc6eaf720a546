using QuantumRayTracing.Noise;

namespace QuantumRayTracing.Experiments;

/// <summary>What `bench estimation` measures (docs/estimation.md).</summary>
/// <param name="Trials">Uniform random means per point.</param>
/// <param name="ImageSize">Output pixels per side of the Qornell box input (4x4 subpixels each); every pixel and channel is one estimate.</param>
/// <param name="Noise">Also measure under depolarizing decay per Grover operator (<see cref="Decays"/>).</param>
/// <param name="Seed">Seed of the means and of every analytic engine.</param>
public sealed record EstimationSettings(int Trials, int ImageSize, bool Noise, ulong Seed)
{
    /// <summary>Query budgets per estimate, from 15 to 3,200.</summary>
    public static readonly long[] Budgets = [15, 30, 60, 120, 240, 480, 960, 1600, 3200];

    /// <summary>The budgets of the noisy sweep.</summary>
    public static readonly long[] NoisyBudgets = [60, 240, 960, 3200];

    /// <summary>
    /// The direct coin's gate-level noise at the device's rates: the device model docs/noise-estimation.md fits to the QCoin
    /// paper's fig. 10 (its one-qubit rate, <see cref="FittedOneQubitRate"/>, and its readout: P0 assumed, P1 from the k = 0 plateau).
    /// </summary>
    public static DeviceNoiseModel DeviceRates => new(FittedOneQubitRate, 0, DeviceFigures.AssumedReadZeroAsOne,
        DeviceFigures.AssumedReadZeroAsOne + 2 * DeviceFigures.MonteCarloError(DeviceFigures.PaperPlateauQueries));

    /// <summary>The one-qubit depolarizing rate the fig. 10 fit chose (docs/noise-estimation.md).</summary>
    public const double FittedOneQubitRate = 1e-2;

    /// <summary>Decays γ per Grover operator of the noisy sweep (fidelity e^(−γ) per operator, on the direct coin).</summary>
    public static readonly double[] Decays = [0.01, 0.03, 0.1];

    /// <summary>QSS counter bits whose run, 2^(t+1) − 1 queries, fits the budgets' range: 15 to 2,047 queries.</summary>
    public static readonly int[] QssCounterBits = [3, 4, 5, 6, 7, 8, 9, 10];

    /// <summary>Counter bits of bit-plane QSS on the pixels: 8 planes of 31, 63 and 127 queries (248, 504, 1,016).</summary>
    public static readonly int[] PlaneCounterBits = [4, 5, 6];

    public const int Subpixels = 4;
}
