namespace QuantumRayTracing.Experiments;

/// <summary>What `bench noise-estimation` measures (docs/noise-estimation.md).</summary>
/// <param name="Trials">Estimates per point of the sweeps: repeated runs at f = ½ for fig. 10, random pixels or means elsewhere.</param>
/// <param name="DeviceRate">The per-gate error standing in for the QCoin paper's device (IBM Q5 Yorktown) in fig. 10 and fig. 1.</param>
/// <param name="ImageSize">Output pixels per side of the fig. 1 image (8x8 subpixels each).</param>
/// <param name="Seed">Seed of every analytic engine and random input.</param>
public sealed record NoiseEstimationSettings(int Trials, double DeviceRate, int ImageSize, ulong Seed)
{
    /// <summary>Default <see cref="DeviceRate"/>: the rate at which QCoin on the direct coin stops improving past k = 5, as on the device (docs/noise-estimation.md).</summary>
    public const double DefaultDeviceRate = 1e-2;

    /// <summary>Per-gate error rates of fig. 10 (both coins).</summary>
    public static readonly double[] StepRates = [0, 1e-5, 1e-4, 1e-3, 3e-3, 1e-2, 3e-2];

    /// <summary>Query budgets of fig. 10.</summary>
    public static readonly long[] StepBudgets = [100, 300, 1000, 3000, 10000];

    /// <summary>Per-gate error rates of the comparison of QSS against QCoin, MLAE and the noisy mean coin.</summary>
    public static readonly double[] NisqRates = [0, 1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2];

    /// <summary>QSS counter bits of the comparison of QSS against QCoin, MLAE and the noisy mean coin; each sets the equal query budget 2^(t+1) − 1.</summary>
    public static readonly int[] NisqCounterBits = [2, 3, 4, 5, 6];

    /// <summary>Subpixels per pixel in the comparison of QSS against QCoin, MLAE and the noisy mean coin (4x4, the thesis's setting).</summary>
    public const int NisqSubpixels = 16;

    /// <summary>Decays γ per Grover operator of the noise-aware comparison (F = e^(−γ)); each is reached by the per-gate error that gives it on the direct coin.</summary>
    public static readonly double[] AwareDecays = [0, 0.01, 0.03, 0.1];

    /// <summary>Query budgets of the noise-aware comparison.</summary>
    public static readonly long[] AwareBudgets = [240, 480, 960, 1600, 3200];
}
