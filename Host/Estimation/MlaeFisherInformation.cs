namespace QuantumRayTracing.Estimation;

/// <summary>
/// What the Fisher information of MLAE's flips predicts about its error under the depolarized coin of
/// <see cref="NoiseAwareMaximumLikelihoodEstimator"/>: P(head) = (1 − a·cos(2kθ)) / 2 with k = 2m+1 and a = e^(−γk/2).
/// A level of n flips adds n·∇p ∇pᵀ / (p(1 − p)) to the information about (θ, γ), with ∂p/∂θ = a·k·sin(2kθ) and
/// ∂p/∂γ = k·a·cos(2kθ) / 4. The Cramér–Rao bound on θ is the inverse's θθ entry (γ estimated jointly) or 1 / I_θθ
/// (γ known); the mean f = sin²θ then has σ_f = sin(2θ)·σ_θ, and a normal error of σ_f has mean absolute value √(2/π)·σ_f.
/// </summary>
/// <remarks>
/// Under noise the information saturates: once a^2 (2m+1)^2 stops growing with m, deeper levels add flips' worth of
/// information at a higher price, so at a fixed schedule the error stops falling as 1/queries. It also degenerates at
/// "anomalous means": where θ is a simple fraction of π the levels' fringes all sit at a few phases, so a change of θ
/// and a change of γ move the head probabilities alike and fitting the decay eats the information about the mean
/// (at f = ½ every level reads ½ whatever the noise).
/// </remarks>
public static class MlaeFisherInformation
{
    /// <summary>A mean is anomalous where fitting the decay costs more than this factor in σ.</summary>
    public const double AnomalyFactor = 1.5;

    /// <summary>Means are kept this far inside [0, 1], where sin(2θ) and the information stay finite.</summary>
    public const double Edge = 1e-9;

    /// <summary>The Cramér–Rao standard deviation of the estimate of mean <paramref name="mean"/> from <paramref name="levels"/> at decay γ.</summary>
    /// <param name="mean">The true mean f ∈ [0, 1] (kept <see cref="Edge"/> inside).</param>
    /// <param name="decay">γ ≥ 0 per Grover operator.</param>
    /// <param name="levels">(m, flips) of each level.</param>
    /// <param name="decayKnown">True: γ known (the bound plain MLAE would reach if told the noise); false: estimated jointly.</param>
    public static double StandardError(double mean, double decay, IReadOnlyList<(int Iterations, int Flips)> levels, bool decayKnown = false)
    {
        var theta = Angle(mean);
        var (tt, tg, gg) = Matrix(theta, decay, levels);
        // The information left about θ once γ is fitted too: the Schur complement I_θθ − I_θγ² / I_γγ.
        var info = decayKnown || gg <= 1e-12 * tt ? tt : tt - tg * tg / gg;
        return info <= 0 ? double.PositiveInfinity : Math.Sin(2 * theta) / Math.Sqrt(info);
    }

    /// <summary>The Cramér–Rao standard deviation of the fitted decay γ at mean <paramref name="mean"/> (θ fitted jointly).</summary>
    public static double DecayStandardError(double mean, double decay, IReadOnlyList<(int Iterations, int Flips)> levels)
    {
        var (tt, tg, gg) = Matrix(Angle(mean), decay, levels);
        var info = tt <= 0 ? gg : gg - tg * tg / tt;
        return info <= 0 ? double.PositiveInfinity : 1 / Math.Sqrt(info);
    }

    private static double Angle(double mean) => Math.Asin(Math.Sqrt(Math.Clamp(mean, Edge, 1 - Edge)));

    // The information matrix about (θ, γ): its θθ, θγ and γγ entries.
    private static (double ThetaTheta, double ThetaDecay, double DecayDecay) Matrix(double theta, double decay, IReadOnlyList<(int Iterations, int Flips)> levels)
    {
        var (tt, tg, gg) = (0.0, 0.0, 0.0);
        foreach (var (m, n) in levels)
        {
            var k = 2 * m + 1;
            var a = NoiseAwareMaximumLikelihoodEstimator.Kept(decay, m);
            var (sin, cos) = Math.SinCos(2 * k * theta);
            // 4p(1 − p) = 1 − a²cos²; without noise (a = 1) the ratio sin² / (1 − cos²) is 1, even at an extremum.
            var variance = 1 - a * a * cos * cos;
            var dTheta = a * k * sin;
            var dDecay = k * a * cos / 4;
            if (variance < 1e-12)
            {
                tt += n * 4.0 * k * k;
                continue;
            }
            var weight = 4.0 * n / variance;
            tt += weight * dTheta * dTheta;
            tg += weight * dTheta * dDecay;
            gg += weight * dDecay * dDecay;
        }
        return (tt, tg, gg);
    }

    /// <summary>The standard deviation as an expected absolute error, √(2/π)·σ.</summary>
    public static double MeanAbsoluteError(double mean, double decay, IReadOnlyList<(int Iterations, int Flips)> levels, bool decayKnown = false) =>
        Math.Sqrt(2 / Math.PI) * StandardError(mean, decay, levels, decayKnown);

    /// <summary>The predicted mean absolute error over uniform random means: the average over the midpoints of <paramref name="cells"/> equal cells of [0, 1].</summary>
    public static double AverageMeanAbsoluteError(double decay, IReadOnlyList<(int Iterations, int Flips)> levels, bool decayKnown = false, int cells = 1000) =>
        Enumerable.Range(0, cells).Average(c => MeanAbsoluteError((c + 0.5) / cells, decay, levels, decayKnown));

    /// <summary>
    /// The anomalous means of a schedule at decay γ, where the information degenerates: the local maxima, over a grid of
    /// <paramref name="cells"/> means, of the information lost by fitting the decay (σ with γ fitted over σ with γ known)
    /// that exceed <paramref name="factor"/>, in increasing order. They sit where θ is a simple fraction of π, so that every
    /// level's fringe sits at one of a few phases: at f = ½ (θ = π/4) each level reads ½ whatever the noise.
    /// </summary>
    public static IReadOnlyList<double> AnomalousMeans(double decay, IReadOnlyList<(int Iterations, int Flips)> levels, double factor = AnomalyFactor, int cells = 2000)
    {
        var means = Enumerable.Range(0, cells).Select(c => (c + 0.5) / cells).ToArray();
        var loss = means.Select(f => StandardError(f, decay, levels) / StandardError(f, decay, levels, decayKnown: true)).ToArray();
        var anomalous = new List<double>();
        for (var c = 0; c < cells; c++)
        {
            var left = c == 0 ? double.NegativeInfinity : loss[c - 1];
            var right = c + 1 == cells ? double.NegativeInfinity : loss[c + 1];
            if (loss[c] > factor && loss[c] >= left && loss[c] > right) anomalous.Add(means[c]);
        }
        return anomalous;
    }

    /// <summary>(m, flips) of each level of an MLAE schedule.</summary>
    public static (int Iterations, int Flips)[] Levels(IReadOnlyList<int> iterations, IReadOnlyList<int> flips) =>
        iterations.Select((m, l) => (m, flips[l])).ToArray();
}
