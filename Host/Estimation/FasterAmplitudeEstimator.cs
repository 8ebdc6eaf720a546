namespace QuantumRayTracing.Estimation;

/// <summary>
/// Faster amplitude estimation (Nakaji, "Faster amplitude estimation", Quantum Information and Computation 20, 2020), within
/// a query budget. It runs on the rescaled coin of head probability f/4 (the mean coin's amplitudes halved), so its angle
/// θ = asin(√(f/4)) lies in [0, π/6], and it reads c(m) = 1 − 2·P(head) = cos(2(2m+1)θ) after m Grover operators.
/// <para>
/// First stage: m = 1, 2, 4, …, <see cref="FirstStageFlips"/> flips each; while 2(2m+1)θ is known to lie in [0, π] the
/// cosine is monotone, so a confidence interval on c(m) gives an interval on θ, intersected with the last. It ends when the
/// next m could take 2(2m+1)θ past π, once the interval fixes the next depth's phase to ±π/3 (until then the round is
/// repeated, its flips pooled).
/// </para>
/// <para>
/// Second stage: m keeps doubling, and each round reads both c(m) and c(m + m_ν) = cos(φ + ν), φ = 2(2m+1)θ and ν = 4m_νθ,
/// with m_ν fixed at the stage's start so that ν is near π/2; ν from the current estimate gives
/// sin φ = (c(m)·cos ν − c(m + m_ν)) / sin ν, and φ = atan2(sin φ, cos φ) gives θ up to a multiple of π/(2m+1), resolved by
/// the nearest to the last estimate. Each round doubles the depth on a fixed number of flips: near-Heisenberg scaling.
/// </para>
/// The depth doubles while the budget pays for N flips at it; then the budget left buys more flips at the current depth,
/// pooled with those made there, and what is left after them (less than one flip's cost) is not spent.
/// </summary>
public sealed class FasterAmplitudeEstimator : AdaptiveMeanEstimator
{
    /// <summary>The chance the first stage's (Clopper–Pearson) intervals miss θ, over all its rounds.</summary>
    public const double Delta = 0.05;

    private const double LargestAngle = Math.PI / 6;

    public FasterAmplitudeEstimator(long queries, int? firstStageFlips = null, int? secondStageFlips = null) : base(queries)
    {
        FirstStageFlips = firstStageFlips ?? DefaultFirstStageFlips;
        SecondStageFlips = secondStageFlips ?? DefaultSecondStageFlips;
        if (FirstStageFlips < 1 || SecondStageFlips < 1) throw new ArgumentOutOfRangeException(nameof(firstStageFlips), "FAE needs at least one flip per round");
    }

    /// <summary>One flip after one Grover operator: the fewest queries FAE can use.</summary>
    public const long MinimumQueries = 3;

    public const int DefaultFirstStageFlips = 8, DefaultSecondStageFlips = 8;

    public int FirstStageFlips { get; }

    public int SecondStageFlips { get; }

    public override string Name => $"fae (N1 = {FirstStageFlips}, N2 = {SecondStageFlips})";

    protected override double AmplitudeScale => 0.5;

    protected override IAdaptiveCoinSearch CreateSearch() => new Search(this);

    private sealed class Search(FasterAmplitudeEstimator owner) : IAdaptiveCoinSearch
    {
        private double _low, _high = LargestAngle;
        private double _angle = LargestAngle / 2;
        // The depth the next round aims at, the depth and flips of the round asked for last, the second stage's offset m_ν.
        private int _next = 1, _m, _asked, _offset;
        // Heads and flips at the current depth, pooled over the rounds that took it (of c(m), and of c(m + m_ν)).
        private int _heads, _flips, _offsetHeads, _offsetFlips;
        private bool _secondStage, _readingOffset, _done, _repeat;

        public (int Iterations, int Flips)? Next(long remaining)
        {
            if (_readingOffset) return (_m + _offset, _asked);
            if (_done) return null;
            var flips = _secondStage ? owner.SecondStageFlips : owner.FirstStageFlips;
            long Cost(int m) => _secondStage ? 4L * m + 2 + 2L * _offset : 2L * m + 1;
            if ((_next != _m || _repeat) && flips * Cost(_next) <= remaining)
            {
                if (!_repeat) (_heads, _flips, _offsetHeads, _offsetFlips) = (0, 0, 0, 0);
                (_m, _asked, _repeat) = (_next, flips, false);
                return (_m, _asked);
            }
            // The budget cannot pay N flips at the next depth: the flips it can pay at the current one (pooled with
            // those already made there), or at m = 1 on a budget too small for N1 flips there; then stop.
            _done = true;
            _m = Math.Max(_m, 1);
            _asked = (int)Math.Min(int.MaxValue, remaining / Cost(_m));
            return _asked >= 1 ? (_m, _asked) : null;
        }

        public void Observe(int heads)
        {
            if (!_secondStage)
            {
                (_heads, _flips) = (_heads + heads, _flips + _asked);
                FirstStage();
                return;
            }
            if (!_readingOffset)
            {
                (_heads, _flips, _readingOffset) = (_heads + heads, _flips + _asked, true);
                return;
            }
            (_offsetHeads, _offsetFlips, _readingOffset) = (_offsetHeads + heads, _offsetFlips + _asked, false);
            var cosine = 1 - 2.0 * _heads / _flips;
            var shifted = 1 - 2.0 * _offsetHeads / _offsetFlips;
            var nu = 4.0 * _offset * _angle;
            // sin ν is near 1 by the choice of m_ν; the guard only keeps a degenerate estimate finite.
            var sine = Math.Abs(Math.Sin(nu)) < 1e-6 ? 0 : (cosine * Math.Cos(nu) - shifted) / Math.Sin(nu);
            var phase = Math.Atan2(sine, cosine);
            var factor = 2.0 * (2 * _m + 1);
            // θ = (φ + 2πρ) / factor for the integer ρ that lands nearest the last estimate.
            var rho = Math.Round((factor * _angle - phase) / (2 * Math.PI));
            _angle = Math.Clamp((phase + 2 * Math.PI * rho) / factor, 0, LargestAngle);
            _next = 2 * _m;
        }

        private void FirstStage()
        {
            var (pLow, pHigh) = BinomialInterval.Of(BinomialIntervalKind.ClopperPearson, _heads, _flips, Delta / Rounds(owner.Queries));
            var factor = 2.0 * (2 * _m + 1);
            // c = 1 − 2p falls as θ grows on [0, π/factor]: a high p is a high θ.
            var (low, high) = (Math.Acos(1 - 2 * pLow) / factor, Math.Acos(1 - 2 * pHigh) / factor);
            (_low, _high) = (Math.Max(_low, low), Math.Min(_high, high));
            if (_low > _high) (_low, _high) = (low, high);
            // The point estimate is the pooled flips' own angle (so no head reads f = 0 exactly), kept inside the interval.
            _angle = Math.Clamp(Math.Acos(1 - 2.0 * _heads / _flips) / factor, _low, _high);
            var doubled = 2.0 * (4 * _m + 1);
            // Double the depth while the cosine stays monotone; then move on once the interval pins the doubled depth's
            // phase to within ±π/3 (else the second stage could not tell which period it is in), and until then repeat.
            if (doubled * _high <= Math.PI) _next = 2 * _m;
            else if (doubled * (_high - _low) / 2 <= Math.PI / 3)
            {
                _secondStage = true;
                _next = 2 * _m;
                // ν = 4m_νθ near π/2, where sin ν is largest.
                _offset = (int)Math.Clamp(Math.Round(Math.PI / (8 * Math.Max(_angle, 1e-9))), 1, owner.Queries);
            }
            else _repeat = true;
        }

        public double Estimate() => 4 * Math.Pow(Math.Sin(_angle), 2);
    }

    // An upper bound on the first stage's rounds: the confidence δ is split over them.
    private static int Rounds(long queries) => Math.Max(1, (int)Math.Ceiling(Math.Log2(queries)));
}
