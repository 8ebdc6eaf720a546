namespace QuantumRayTracing.Experiments;

/// <summary>
/// The loose acceptance bound a soak holds quantum renders to: the most pixels (#Dpix) that may differ
/// from the classical render of the same options. A quantum search misses a closer primitive or an
/// occluder with some small probability, so some wrong pixels are expected; an engine that samples the
/// wrong distribution (or none) gets most pixels wrong. The bound treats pixels as independent, each wrong
/// with probability <see cref="Rate"/>, and allows the count whose upper tail holds at most
/// <see cref="FalseFailure"/>. The analytic engine's worst render over 40 seeds on every shipped scene had 5
/// wrong pixels of 256 at 16x16 (the bound: 51) and 5 of 16 at 4x4 with two rounds (the bound: 9;
/// docs/reliability.md), so the bound is loose by design: it catches a broken engine, not a slightly worse
/// one. At 2x2 it allows every pixel, and the check says nothing.
/// </summary>
public static class DifferentPixelBound
{
    /// <summary>Assumed probability that one pixel of a correct quantum render differs from the classical one.</summary>
    public const double Rate = 0.1;

    /// <summary>Probability that a correct render exceeds the bound.</summary>
    public const double FalseFailure = 1e-6;

    /// <summary>The smallest k with P(X &gt; k) ≤ <paramref name="falseFailure"/> for X ~ Binomial(<paramref name="pixels"/>, <paramref name="rate"/>).</summary>
    public static int Max(int pixels, double rate = Rate, double falseFailure = FalseFailure)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(pixels);
        if (rate <= 0) return 0;
        if (rate >= 1) return pixels;
        // P(X = k) by the recurrence p(k+1) = p(k) · (n − k)/(k + 1) · rate/(1 − rate), from p(0) in logs.
        var logRatio = Math.Log(rate) - Math.Log(1 - rate);
        var logP = pixels * Math.Log(1 - rate);
        var below = 0.0;
        for (var k = 0; k <= pixels; k++)
        {
            below += Math.Exp(logP);
            if (1 - below <= falseFailure) return k;
            logP += Math.Log(pixels - k) - Math.Log(k + 1) + logRatio;
        }
        return pixels;
    }
}
