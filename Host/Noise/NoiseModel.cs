using System.Globalization;

namespace QuantumRayTracing.Noise;

/// <summary>
/// Hardware noise as the QDK's noisy simulator applies it: after every gate (and before every
/// measurement), on each qubit the operation touches, a Pauli X, Y or Z with probabilities
/// <see cref="Px"/>, <see cref="Py"/>, <see cref="Pz"/>; and a qubit lost with probability
/// <see cref="QubitLoss"/> per operation. Validated once, where it is made.
/// </summary>
public sealed record NoiseModel
{
    /// <summary>The ideal machine: the engines take their noiseless path.</summary>
    public static readonly NoiseModel None = new(0, 0, 0, 0);

    public NoiseModel(double px, double py, double pz, double qubitLoss = 0)
    {
        if (Problem(px, py, pz) is { } pauli) throw new ArgumentException(pauli);
        if (LossProblem(qubitLoss) is { } loss) throw new ArgumentException(loss);
        (Px, Py, Pz, QubitLoss) = (px, py, pz, qubitLoss);
    }

    /// <summary>Depolarizing Pauli noise of total probability <paramref name="perGate"/>: a third each of X, Y and Z.</summary>
    public static NoiseModel Depolarizing(double perGate, double qubitLoss = 0) => new(perGate / 3, perGate / 3, perGate / 3, qubitLoss);

    public double Px { get; }

    public double Py { get; }

    public double Pz { get; }

    /// <summary>Probability that an operation loses a qubit it touches, in [0, 1).</summary>
    public double QubitLoss { get; }

    /// <summary>Probability of some Pauli error per qubit per operation: px + py + pz.</summary>
    public double PerGate => Px + Py + Pz;

    public bool IsNoiseless => PerGate == 0 && QubitLoss == 0;

    /// <summary>The model as every printed result names it.</summary>
    public string Description()
    {
        if (IsNoiseless) return "noiseless (ideal gates)";
        var pauli = PerGate == 0 ? "no Pauli noise"
            : Px == Py && Py == Pz
            ? $"depolarizing Pauli noise p = {G(PerGate)} per gate and qubit (p/3 each of X, Y, Z)"
            : $"Pauli noise per gate and qubit px = {G(Px)}, py = {G(Py)}, pz = {G(Pz)}";
        return QubitLoss > 0 ? $"{pauli}, qubit loss {G(QubitLoss)} per operation" : pauli;
    }

    public override string ToString() => Description();

    /// <summary>The model <c>--noise</c> (<see cref="ParsePauli"/>; null: no Pauli noise) and <c>--qubit-loss</c> give.</summary>
    public static NoiseModel Of(string? pauli, double loss) => pauli is null
        ? loss == 0 ? None : new NoiseModel(0, 0, 0, loss)
        : ParsePauli(pauli, out var problem) is var (px, py, pz) ? new NoiseModel(px, py, pz, loss) : throw new ArgumentException(problem, nameof(pauli));

    /// <summary>
    /// Parses <c>--noise</c>: one number P (P/3 each of X, Y, Z) or three, <c>px,py,pz</c>. Null and a
    /// problem naming what is wrong when the text is not a valid model.
    /// </summary>
    public static (double Px, double Py, double Pz)? ParsePauli(string text, out string? problem)
    {
        var parts = text.Split(',');
        var values = new double[parts.Length];
        problem = null;
        if (parts.Length is not (1 or 3))
        {
            problem = $"'{text}' is neither one probability P nor three, px,py,pz";
            return null;
        }
        for (var k = 0; k < parts.Length; k++)
        {
            if (!double.TryParse(parts[k].Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out values[k]))
            {
                problem = $"'{parts[k].Trim()}' is not a number";
                return null;
            }
        }
        var pauli = parts.Length == 1 ? (values[0] / 3, values[0] / 3, values[0] / 3) : (values[0], values[1], values[2]);
        if (parts.Length == 1 && (double.IsNaN(values[0]) || double.IsInfinity(values[0]) || values[0] < 0 || values[0] > 1))
        {
            problem = $"P = {G(values[0])} is not a probability in [0, 1]";
            return null;
        }
        problem = Problem(pauli.Item1, pauli.Item2, pauli.Item3);
        return problem is null ? pauli : null;
    }

    /// <summary>Why three Pauli probabilities are not a model, or null.</summary>
    public static string? Problem(double px, double py, double pz)
    {
        foreach (var (name, p) in new[] { ("px", px), ("py", py), ("pz", pz) })
        {
            if (double.IsNaN(p) || double.IsInfinity(p)) return $"{name} is {p}, not a probability";
            if (p < 0) return $"{name} = {G(p)} is negative";
        }
        if (px + py + pz > 1) return $"px + py + pz = {G(px + py + pz)} exceeds 1";
        return null;
    }

    /// <summary>Why a qubit-loss probability is not valid (it must lie in [0, 1)), or null.</summary>
    public static string? LossProblem(double loss) =>
        double.IsNaN(loss) || double.IsInfinity(loss) ? $"{loss} is not a probability"
        : loss < 0 || loss >= 1 ? $"{G(loss)} lies outside [0, 1)"
        : null;

    private static string G(double value) => value.ToString("G4", CultureInfo.InvariantCulture);
}
