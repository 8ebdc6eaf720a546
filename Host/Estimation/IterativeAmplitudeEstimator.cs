namespace QuantumRayTracing.Estimation;

/// <summary>
/// Iterative quantum amplitude estimation (Grinko, Gacon, Zoufal and Woerner, npj Quantum Information 7:52, 2021) within a
/// query budget. With the mean f = sin²θ, a flip after k Grover operators is a head with probability
/// (1 − cos(Kθ)) / 2, K = 4k + 2. IQAE keeps a confidence interval [θ_l, θ_u] ⊂ [0, π/2] and each round takes the largest
/// k (at least twice the last K, else the last k) for which [Kθ_l, Kθ_u] lies inside one half-period [0, π] or [π, 2π]
/// modulo 2π, where the head probability is monotone in θ; it flips the coin <see cref="FlipsPerRound"/> times at that k,
/// forms a confidence interval of the head probability from all the flips at this k (Clopper–Pearson or Chernoff, at
/// level α/T over T = ⌈log2(πQ/8)⌉ rounds), and maps it back into the half-period to narrow [θ_l, θ_u].
/// </summary>
/// <remarks>
/// The original estimate, the middle of the last interval, is biased at some means (Miyamoto, EPJ Quantum Technology 11:42,
/// 2024): which k the last rounds take, and when the interval stops, depend on the flips the estimate is made from. The fix
/// (the default, <see cref="RerunLastRound"/>): once another round would leave less than <see cref="FinalShare"/> of the budget, the k of the
/// next round is fixed from the interval, all the budget left is flipped at it, and the estimate is made from those fresh
/// flips alone, mapped into the half-period the interval has fixed. Without the fix the rounds go on until the budget
/// cannot pay another, the last one taking the flips that are left, and the estimate is the interval's middle.
/// </remarks>
public sealed class IterativeAmplitudeEstimator : AdaptiveMeanEstimator
{
    /// <summary>α, the chance that the final interval misses the mean.</summary>
    public const double Alpha = 0.05;

    /// <summary>With the fix, the last round starts once another round would leave less than this share of the budget, and takes all that is left.</summary>
    public const double FinalShare = 0.4;

    /// <param name="queries">Budget per item.</param>
    /// <param name="flipsPerRound">N, flips per round; default <see cref="DefaultFlipsPerRound"/>.</param>
    /// <param name="interval">How each round's confidence interval is formed.</param>
    /// <param name="rerunLastRound">True (default): Miyamoto's fix; false: the original estimate, which is biased.</param>
    public IterativeAmplitudeEstimator(long queries, int? flipsPerRound = null, BinomialIntervalKind interval = BinomialIntervalKind.ClopperPearson, bool rerunLastRound = true)
        : base(queries)
    {
        FlipsPerRound = flipsPerRound ?? DefaultFlipsPerRound;
        if (FlipsPerRound < 1) throw new ArgumentOutOfRangeException(nameof(flipsPerRound), flipsPerRound, "IQAE needs at least one flip per round");
        Interval = interval;
        RerunLastRound = rerunLastRound;
        Rounds = Math.Max(1, (int)Math.Ceiling(Math.Log2(Math.PI * queries / 8)));
    }

    /// <summary>The default N (the best of 4, 8, 16 and 32 at 240 and 3,200 queries, docs/supersampling.md).</summary>
    public const int DefaultFlipsPerRound = 32;

    public int FlipsPerRound { get; }

    public BinomialIntervalKind Interval { get; }

    public bool RerunLastRound { get; }

    /// <summary>T, the rounds the confidence level is split over.</summary>
    public int Rounds { get; }

    public override string Name => $"iqae (N = {FlipsPerRound}{(Interval == BinomialIntervalKind.Chernoff ? ", Chernoff" : "")}{(RerunLastRound ? "" : ", without the bias fix")})";

    protected override IAdaptiveCoinSearch CreateSearch() => new Search(this);

    private sealed class Search(IterativeAmplitudeEstimator owner) : IAdaptiveCoinSearch
    {
        private double _low, _high = Math.PI / 2;
        private int _k;
        private bool _upper = true;
        // Heads and flips at the current k, over the rounds that took it; the flips asked for last.
        private int _heads, _flips, _asked;
        private bool _final, _done;
        private double? _finalAngle;

        public (int Iterations, int Flips)? Next(long remaining)
        {
            if (_done || remaining < 1) return null;
            var reserve = owner.RerunLastRound ? (long)(FinalShare * owner.Queries) : 0;
            var affordable = (int)Math.Min(int.MaxValue / 4, (remaining - 1) / 2);
            var (k, upper) = NextPower(_low, _high, _k, _upper, affordable);
            var cost = (long)owner.FlipsPerRound * (2 * k + 1);
            if (remaining - cost < reserve || cost > remaining)
            {
                // The last round: all that is left, at the largest k both the interval and the budget allow.
                _final = true;
                (k, upper) = LargestFitting(_low, _high, Math.Min(k, affordable));
            }
            if (k != _k) (_heads, _flips) = (0, 0);
            (_k, _upper) = (k, upper);
            _asked = _final ? (int)Math.Min(int.MaxValue, remaining / (2 * k + 1)) : owner.FlipsPerRound;
            return (k, _asked);
        }

        public void Observe(int heads)
        {
            _done = _final;
            if (_final && owner.RerunLastRound)
            {
                // Miyamoto's fix: the estimate comes from the last round's own flips only.
                _finalAngle = Angle(_low, _k, _upper, (double)heads / _asked);
                return;
            }
            (_heads, _flips) = (_heads + heads, _flips + _asked);
            var (pLow, pHigh) = BinomialInterval.Of(owner.Interval, _heads, _flips, Alpha / owner.Rounds);
            var (low, high) = (Angle(_low, _k, _upper, _upper ? pLow : pHigh), Angle(_low, _k, _upper, _upper ? pHigh : pLow));
            (_low, _high) = (Math.Clamp(low, 0, Math.PI / 2), Math.Clamp(high, 0, Math.PI / 2));
        }

        public double Estimate() => _finalAngle is { } angle
            ? Math.Pow(Math.Sin(angle), 2)
            : (Math.Pow(Math.Sin(_low), 2) + Math.Pow(Math.Sin(_high), 2)) / 2;
    }

    /// <summary>
    /// θ in the half-period of Kθ that θ_l's lies in, K = 4k + 2, whose head probability (1 − cos Kθ) / 2 is <paramref name="p"/>.
    /// </summary>
    public static double Angle(double low, int k, bool upper, double p)
    {
        var factor = 4.0 * k + 2;
        var phase = Math.Acos(Math.Clamp(1 - 2 * p, -1, 1));
        var periods = Math.Floor(factor * low / (2 * Math.PI));
        return (2 * Math.PI * periods + (upper ? phase : 2 * Math.PI - phase)) / factor;
    }

    /// <summary>
    /// IQAE's choice of the next k: the largest K = 4k + 2 ≤ π / (θ_u − θ_l) (and k ≤ <paramref name="largest"/>), at least
    /// twice the current K, for which [Kθ_l, Kθ_u] mod 2π lies in [0, π] (upper half-plane) or [π, 2π]; else the current k.
    /// </summary>
    public static (int K, bool Upper) NextPower(double low, double high, int current, bool upper, int largest)
    {
        var currentFactor = 4L * current + 2;
        var widest = high - low <= 0 ? long.MaxValue : (long)Math.Min(4.0 * largest + 2, Math.Floor(Math.PI / (high - low)));
        widest = Math.Min(widest, 4L * largest + 2);
        for (var factor = widest - ((widest - 2) % 4 + 4) % 4; factor >= 2 * currentFactor; factor -= 4)
            if (HalfPlane(low, high, factor) is { } half) return ((int)((factor - 2) / 4), half);
        return (current, upper);
    }

    /// <summary>The largest k ≤ <paramref name="largest"/> whose [Kθ_l, Kθ_u] lies in one half-period (k = 0 always does).</summary>
    public static (int K, bool Upper) LargestFitting(double low, double high, int largest)
    {
        for (var k = Math.Max(0, largest); k > 0; k--)
            if (HalfPlane(low, high, 4L * k + 2) is { } half) return (k, half);
        return (0, true);
    }

    // True when [Kθ_l, Kθ_u] mod 2π lies in [0, π], false in [π, 2π], null when it straddles.
    private static bool? HalfPlane(double low, double high, long factor)
    {
        if (factor * (high - low) > Math.PI) return null;
        var a = Wrap(factor * low);
        var b = Wrap(factor * high);
        if (a > b) return null;
        if (b <= Math.PI) return true;
        if (a >= Math.PI) return false;
        return null;
    }

    private static double Wrap(double x) => x - 2 * Math.PI * Math.Floor(x / (2 * Math.PI));
}
