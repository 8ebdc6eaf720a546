namespace QuantumRayTracing.Estimation;

/// <summary>
/// The grid posterior search of <see cref="BayesianAmplitudeEstimator"/>, for any circuit whose outcome ("head") has
/// probability sin²(c(k)·θ + φ) at power k (<see cref="PosteriorFringe"/>): a posterior over θ ∈ [0, π/2] on
/// <see cref="GridPoints"/> points, prior uniform in f = sin²θ; each round the power of most expected variance reduction of f
/// per query (a shot at power k costs 1 + 2k), about <see cref="RoundShare"/> of what was spent so far; the grid rebuilt on
/// a narrower window from the stored outcomes when all but 1e-9 of the posterior lies in under half of it. The estimate is
/// the posterior median of f.
/// </summary>
internal sealed class GridPosteriorSearch : IAdaptiveCoinSearch
{
    public const int GridPoints = 512;

    public const double RoundShare = 0.25;

    // Candidate powers grow by this factor: 0, 1, 2, 3, 4, 5, 6, 7, 9, 12, 15, …
    private const double Growth = 1.25;

    // A candidate's fringe (period π / its factor) must span at least this many grid steps.
    private const double StepsPerFringe = 8;

    private const double Tail = 1e-9;

    private readonly Dictionary<int, (int Heads, int Flips)> _seen = [];
    private readonly double[] _angles = new double[GridPoints], _means = new double[GridPoints], _weights = new double[GridPoints];
    private double _low, _high = Math.PI / 2;
    private readonly PosteriorFringe _fringe;
    private long _spent;
    private int _m, _asked;


    public GridPosteriorSearch(PosteriorFringe fringe)
    {
        _fringe = fringe;
        Rebuild(0, Math.PI / 2);
    }

    public (int Iterations, int Flips)? Next(long remaining)
    {
        if (remaining < 1) return null;
        _m = BestPower(remaining);
        var cost = 1 + 2L * _m;
        var wanted = Math.Max(1, (long)Math.Round(RoundShare * _spent / cost));
        _asked = (int)Math.Min(wanted, remaining / cost);
        _spent += _asked * cost;
        return (_m, _asked);
    }

    public void Observe(int heads)
    {
        var (h, n) = _seen.GetValueOrDefault(_m);
        _seen[_m] = (h + heads, n + _asked);
        for (var i = 0; i < GridPoints; i++)
        {
            var s = _fringe.Sine(_m, _angles[i]);
            _weights[i] *= Math.Pow(s * s, heads) * Math.Pow(1 - s * s, _asked - heads);
        }
        if (!Normalise()) Rebuild(_low, _high);
        var (low, high) = Support();
        if (high - low < 0.5 * (_high - _low)) Rebuild(low, high);
    }

    public double Estimate()
    {
        var cumulative = 0.0;
        for (var i = 0; i < GridPoints; i++)
        {
            cumulative += _weights[i];
            if (cumulative >= 0.5) return Math.Pow(Math.Sin(_angles[i]), 2);
        }
        return Math.Pow(Math.Sin(_angles[^1]), 2);
    }

    // The m of most expected variance reduction per query, among those the grid resolves and the budget pays.
    private int BestPower(long remaining)
    {
        var step = (_high - _low) / (GridPoints - 1);
        var variance = Variance();
        var (best, bestGain) = (0, double.NegativeInfinity);
        foreach (var m in Candidates())
        {
            if (1 + 2L * m > remaining || step > 0 && Math.PI / _fringe.Factor(m) < StepsPerFringe * step) break;
            var gain = (variance - ExpectedVariance(m)) / (1 + 2.0 * m);
            if (gain > bestGain) (best, bestGain) = (m, gain);
        }
        return best;
    }

    private IEnumerable<int> Candidates()
    {
        if (_fringe.FirstPower == 0) yield return 0;
        var last = 0;
        for (var x = 1.0; x < int.MaxValue / 4; x *= Growth)
        {
            var m = (int)Math.Round(x);
            if (m > last) yield return last = m;
        }
    }

    // E over the flip's outcome of the posterior variance of f after one flip at m.
    private double ExpectedVariance(int m)
    {
        double headMass = 0, headF = 0, headF2 = 0, tailMass = 0, tailF = 0, tailF2 = 0;
        for (var i = 0; i < GridPoints; i++)
        {
            var s = _fringe.Sine(m, _angles[i]);
            var p = s * s;
            var f = _means[i];
            var (wh, wt) = (_weights[i] * p, _weights[i] * (1 - p));
            (headMass, headF, headF2) = (headMass + wh, headF + wh * f, headF2 + wh * f * f);
            (tailMass, tailF, tailF2) = (tailMass + wt, tailF + wt * f, tailF2 + wt * f * f);
        }
        double Variance(double mass, double sum, double squares) => mass <= 0 ? 0 : squares / mass - sum * sum / (mass * mass);
        return headMass * Variance(headMass, headF, headF2) + tailMass * Variance(tailMass, tailF, tailF2);
    }

    // The posterior variance of f.
    private double Variance()
    {
        double mean = 0, squares = 0;
        for (var i = 0; i < GridPoints; i++)
        {
            var f = _means[i];
            mean += _weights[i] * f;
            squares += _weights[i] * f * f;
        }
        return squares - mean * mean;
    }

    // The narrowest window holding all but Tail of the posterior, widened by a grid step each side.
    private (double Low, double High) Support()
    {
        var step = (_high - _low) / (GridPoints - 1);
        var (first, last) = (0, GridPoints - 1);
        var cumulative = 0.0;
        while (first < GridPoints - 1 && cumulative + _weights[first] < Tail / 2) cumulative += _weights[first++];
        cumulative = 0;
        while (last > first && cumulative + _weights[last] < Tail / 2) cumulative += _weights[last--];
        return (Math.Max(0, _angles[first] - step), Math.Min(Math.PI / 2, _angles[last] + step));
    }

    // The grid on [low, high], its weights the prior (uniform in f: density sin 2θ) times the likelihood of every flip seen.
    private void Rebuild(double low, double high)
    {
        (_low, _high) = (low, high);
        var logs = new double[GridPoints];
        for (var i = 0; i < GridPoints; i++)
        {
            var theta = low + (high - low) * i / (GridPoints - 1);
            _angles[i] = theta;
            _means[i] = Math.Pow(Math.Sin(theta), 2);
            var log = Math.Log(Math.Max(Math.Sin(2 * theta), 1e-300));
            foreach (var (m, (h, n)) in _seen)
            {
                var s = _fringe.Sine(m, theta);
                var p = s * s;
                if (h > 0) log += h * Math.Log(Math.Max(p, 1e-300));
                if (n > h) log += (n - h) * Math.Log(Math.Max(1 - p, 1e-300));
            }
            logs[i] = log;
        }
        var top = logs.Max();
        for (var i = 0; i < GridPoints; i++) _weights[i] = Math.Exp(logs[i] - top);
        Normalise();
    }

    // Scales the weights to sum to 1; false when they underflowed to nothing.
    private bool Normalise()
    {
        var total = _weights.Sum();
        if (!(total > 1e-250) || double.IsInfinity(total)) return false;
        for (var i = 0; i < GridPoints; i++) _weights[i] /= total;
        return true;
    }
}
