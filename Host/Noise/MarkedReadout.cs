using QuantumRayTracing.Search;

namespace QuantumRayTracing.Noise;

/// <summary>
/// P(reading a marked index) when a readout error flips each measured bit of the index register, from each of the three
/// distributions the depolarizing form mixes: a marked index uniformly (<see cref="FromMarked"/>), an unmarked one of
/// [0, N) uniformly (<see cref="FromUnmarked"/>) and any value of the register uniformly (<see cref="FromUniform"/>).
/// With no readout error they are 1, 0 and t / 2^n.
/// </summary>
public sealed record MarkedReadout(double FromMarked, double FromUnmarked, double FromUniform)
{
    /// <summary>The three probabilities for <paramref name="marked"/> under <paramref name="rates"/>' readout error (their gates play no part).</summary>
    public static MarkedReadout Of(CircuitRates rates, MarkedSet marked)
    {
        ArgumentNullException.ThrowIfNull(rates);
        ArgumentNullException.ThrowIfNull(marked);
        var n = SearchRegisters.For(marked.Count).IndexQubits;
        var values = 1 << n;
        double Read(Func<int, bool> holds)
        {
            var distribution = new double[values];
            var count = 0;
            for (var v = 0; v < values; v++) if (holds(v)) count++;
            if (count == 0) return 0;
            for (var v = 0; v < values; v++) distribution[v] = holds(v) ? 1.0 / count : 0;
            for (var q = 0; q < n; q++) distribution = FlipBit(distribution, q, rates.ReadZeroAsOne, rates.ReadOneAsZero);
            var total = 0.0;
            foreach (var m in marked.Indices) total += distribution[m];
            return total;
        }
        return new MarkedReadout(Read(marked.Contains), Read(v => v < marked.Count && !marked.Contains(v)), Read(_ => true));
    }

    /// <summary>
    /// The distribution of values read from <paramref name="distribution"/> when bit <paramref name="q"/> is read wrong: a 0 as 1
    /// with <paramref name="zeroAsOne"/>, a 1 as 0 with <paramref name="oneAsZero"/>.
    /// </summary>
    public static double[] FlipBit(double[] distribution, int q, double zeroAsOne, double oneAsZero)
    {
        ArgumentNullException.ThrowIfNull(distribution);
        var read = new double[distribution.Length];
        for (var v = 0; v < distribution.Length; v++)
        {
            var turn = (v >> q & 1) == 1 ? oneAsZero : zeroAsOne;
            read[v] += (1 - turn) * distribution[v];
            read[v ^ (1 << q)] += turn * distribution[v];
        }
        return read;
    }

    /// <summary>P(reading a marked index) of a run that is ideal with <paramref name="fidelity"/> (reading a marked index with <paramref name="idealMarked"/>), else uniform.</summary>
    public double Read(double idealMarked, double fidelity) =>
        fidelity * (idealMarked * FromMarked + (1 - idealMarked) * FromUnmarked) + (1 - fidelity) * FromUniform;
}
