namespace QuantumRayTracing.Noise;

/// <summary>
/// P(marked) of a Grover run over a K-value index register with t marked values whose every iteration, after its oracle,
/// leaves the register uniformly mixed with probability 1 − F and otherwise multiplies each pair class's coherence by its
/// survival (<see cref="IterationChannels"/>), the last iteration's survivals its own. Every channel and the ideal run treat the marked values alike and the unmarked
/// alike, so the density matrix keeps five numbers: a marked and an unmarked value's probability, and the coherence of two
/// marked, two unmarked, and a marked and an unmarked value. The diffusion 2|s⟩⟨s| − I maps ρ to
/// ρ + 4⟨s|ρ|s⟩/K − 2(R_a + R_b)/K entry by entry, R_a the row sum of a's class.
/// </summary>
public static class DephasedSearch
{
    /// <summary>P(marked) when every iteration has the survivals <paramref name="iteration"/>.</summary>
    public static double MarkedProbability(int register, int marked, int iterations, double outside, Iteration iteration) =>
        MarkedProbability(register, marked, iterations, outside, iteration, iteration);

    /// <summary>One iteration's survivals: of the run (not mixed), and of each class's coherence.</summary>
    public readonly record struct Iteration(double Uniform, double Cross, double Unmarked, double Marked)
    {
        public static readonly Iteration Ideal = new(1, 1, 1, 1);
    }

    /// <summary>
    /// P(marked) after <paramref name="iterations"/> iterations (<paramref name="inner"/> but the last, <paramref name="last"/>)
    /// and the preparation and measurement's survival <paramref name="outside"/> (the rest of that part reads uniformly).
    /// </summary>
    public static double MarkedProbability(int register, int marked, int iterations, double outside, Iteration inner, Iteration last)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(register, 1);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(marked, register);
        if (marked == 0) return 0;
        double k = register, t = marked, u = register - marked;
        // The uniform start: every entry 1/K.
        double dm = 1 / k, du = 1 / k, mm = 1 / k, uu = 1 / k, mu = 1 / k;
        for (var j = 0; j < iterations; j++)
        {
            var iteration = j < iterations - 1 ? inner : last;
            mu = -mu; // the oracle's sign on the marked values
            (mm, uu, mu) = (mm * iteration.Marked, uu * iteration.Unmarked, mu * iteration.Cross);
            var f = iteration.Uniform;
            (dm, du, mm, uu, mu) = (f * dm + (1 - f) / k, f * du + (1 - f) / k, f * mm, f * uu, f * mu);
            var rowMarked = dm + (t - 1) * mm + u * mu;
            var rowUnmarked = du + (u - 1) * uu + t * mu;
            var mean = (t * rowMarked + u * rowUnmarked) / k;
            (dm, mm) = (dm + 4 * (mean - rowMarked) / k, mm + 4 * (mean - rowMarked) / k);
            (du, uu) = (du + 4 * (mean - rowUnmarked) / k, uu + 4 * (mean - rowUnmarked) / k);
            mu += (4 * mean - 2 * (rowMarked + rowUnmarked)) / k;
        }
        return outside * t * dm + (1 - outside) * t / k;
    }
}
