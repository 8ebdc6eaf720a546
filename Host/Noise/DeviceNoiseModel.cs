using System.Globalization;

namespace QuantumRayTracing.Noise;

/// <summary>
/// A device noise model: depolarizing Pauli noise (p/3 each of X, Y, Z on every qubit a gate touches) at one rate after
/// one-qubit gates and another after gates on two or more qubits, no noise at the measurement itself, and a readout
/// error that flips each measured bit classically: a 0 is read as 1 with probability <see cref="ReadZeroAsOne"/>, a 1 as
/// 0 with <see cref="ReadOneAsZero"/>. Validated once, where it is made.
/// </summary>
public sealed record DeviceNoiseModel
{
    public DeviceNoiseModel(double oneQubit, double twoQubit, double readZeroAsOne = 0, double readOneAsZero = 0)
    {
        foreach (var (name, p) in new[] { ("1q", oneQubit), ("2q", twoQubit), ("P0", readZeroAsOne), ("P1", readOneAsZero) })
            if (Problem(name, p) is { } problem) throw new ArgumentException(problem);
        (OneQubit, TwoQubit, ReadZeroAsOne, ReadOneAsZero) = (oneQubit, twoQubit, readZeroAsOne, readOneAsZero);
    }

    /// <summary>Depolarizing probability on the qubit after each one-qubit gate.</summary>
    public double OneQubit { get; }

    /// <summary>Depolarizing probability on each qubit after each gate on two or more qubits.</summary>
    public double TwoQubit { get; }

    /// <summary>P0 = P(read 1 | 0).</summary>
    public double ReadZeroAsOne { get; }

    /// <summary>P1 = P(read 0 | 1).</summary>
    public double ReadOneAsZero { get; }

    /// <summary>An engine's device model, refused beside a Pauli <paramref name="noise"/> model other than the ideal one: the two are alternatives.</summary>
    public static DeviceNoiseModel? Alone(DeviceNoiseModel? device, NoiseModel? noise) => device is not null && noise is { IsNoiseless: false }
        ? throw new ArgumentException("give a Pauli noise model or a device model, not both", nameof(device))
        : device;

    public bool HasReadoutError => ReadZeroAsOne > 0 || ReadOneAsZero > 0;

    /// <summary>No gate noise and no readout error: the engines take their noiseless path.</summary>
    public bool IsNoiseless => OneQubit == 0 && TwoQubit == 0 && !HasReadoutError;

    /// <summary>The model with its readout error left out: the negative control of a readout-sensitive check.</summary>
    public DeviceNoiseModel WithoutReadout() => new(OneQubit, TwoQubit);

    /// <summary>The probability of reading 1 from a bit that is 1 with probability <paramref name="p"/>: P0 + (1 − P0 − P1) p.</summary>
    public double ReadOne(double p) => ReadZeroAsOne + (1 - ReadZeroAsOne - ReadOneAsZero) * p;

    /// <summary>The model as every printed result names it.</summary>
    public string Description() =>
        $"device model: depolarizing p1 = {G(OneQubit)} after one-qubit gates, p2 = {G(TwoQubit)} on each qubit after gates on two or more qubits, "
        + (HasReadoutError ? $"readout error P(1|0) = {G(ReadZeroAsOne)}, P(0|1) = {G(ReadOneAsZero)}" : "no readout error");

    public override string ToString() => Description();

    /// <summary>
    /// Parses <c>--device-noise</c> (<c>1q=P,2q=P</c>, either key may be left out for 0) and <c>--readout-error</c>
    /// (<c>P</c> for both flips or <c>P0,P1</c>); null text means none. Null and a one-line problem when invalid.
    /// </summary>
    public static DeviceNoiseModel? Parse(string? gates, string? readout, out string? problem)
    {
        problem = null;
        var (oneQubit, twoQubit) = (0.0, 0.0);
        if (gates is not null)
        {
            foreach (var part in gates.Split(','))
            {
                var pair = part.Split('=');
                if (pair.Length != 2 || pair[0].Trim() is not ("1q" or "2q"))
                {
                    problem = $"--device-noise: '{part.Trim()}' is not 1q=P or 2q=P";
                    return null;
                }
                if (ParseProbability(pair[1], $"--device-noise: {pair[0].Trim()}", out problem) is not { } p) return null;
                if (pair[0].Trim() == "1q") oneQubit = p;
                else twoQubit = p;
            }
        }
        var (zero, one) = (0.0, 0.0);
        if (readout is not null)
        {
            var parts = readout.Split(',');
            if (parts.Length is not (1 or 2))
            {
                problem = $"--readout-error: '{readout}' is neither one probability P nor two, P0,P1";
                return null;
            }
            if (ParseProbability(parts[0], "--readout-error: P0", out problem) is not { } p0) return null;
            if (ParseProbability(parts[^1], "--readout-error: P1", out problem) is not { } p1) return null;
            (zero, one) = (p0, p1);
            if (zero + one >= 1)
            {
                problem = $"--readout-error: P0 + P1 = {G(zero + one)} must stay below 1 (the readout would carry no information)";
                return null;
            }
        }
        return new DeviceNoiseModel(oneQubit, twoQubit, zero, one);
    }

    private static double? ParseProbability(string text, string name, out string? problem)
    {
        problem = null;
        if (!double.TryParse(text.Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out var p))
        {
            problem = $"{name}: '{text.Trim()}' is not a number";
            return null;
        }
        problem = Problem(name, p);
        return problem is null ? p : null;
    }

    private static string? Problem(string name, double p) =>
        double.IsNaN(p) || double.IsInfinity(p) || p < 0 || p > 1 ? $"{name} = {G(p)} is not a probability in [0, 1]" : null;

    private static string G(double value) => value.ToString("G4", CultureInfo.InvariantCulture);
}
