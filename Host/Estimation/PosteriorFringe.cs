namespace QuantumRayTracing.Estimation;

/// <summary>
/// What one shot at power k tells about θ (f = sin²θ): its outcome has probability sin²(c(k)·θ + φ), c(k) = a·k + b.
/// The fringe's period in θ is π / c(k).
/// </summary>
/// <param name="PerPower">a.</param>
/// <param name="Offset">b.</param>
/// <param name="Phase">φ.</param>
/// <param name="FirstPower">The least power worth a shot (at c = 0 a shot says nothing).</param>
public sealed record PosteriorFringe(double PerPower, double Offset, double Phase, int FirstPower)
{
    /// <summary>A flip of the mean coin after m Grover operators: head with probability sin²((2m+1)θ).</summary>
    public static readonly PosteriorFringe CoinFlip = new(2, 1, 0, 0);

    /// <summary>
    /// The single-ancilla phase-estimation shot (<see cref="AncillaPhaseRequest"/>): ancilla 0 with probability
    /// ½ + ½·cos(2kθ) = cos²(kθ) = sin²(kθ + π/2).
    /// </summary>
    public static readonly PosteriorFringe AncillaPhase = new(1, 0, Math.PI / 2, 1);

    public double Factor(int power) => PerPower * power + Offset;

    public double Sine(int power, double theta) => Math.Sin(Factor(power) * theta + Phase);
}
