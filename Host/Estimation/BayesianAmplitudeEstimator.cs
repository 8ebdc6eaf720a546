namespace QuantumRayTracing.Estimation;

/// <summary>
/// Bayesian amplitude estimation (after Ramôa and Santos, arXiv 2412.04394): a posterior over the angle θ of f = sin²θ,
/// kept on a grid, and each round's Grover power m chosen where one flip is expected to shrink the posterior variance of f
/// most per query, (Var f − E[Var f | flip at m]) / (1 + 2m). Without noise the chosen m grows as the posterior narrows,
/// about as 1/σ, which gives the Heisenberg scaling. The estimate is the posterior median of f (the best guess under
/// absolute error).
/// </summary>
/// <remarks>
/// The prior is uniform in f. Each round spends about <see cref="RoundShare"/> of what was spent so far (at least one flip)
/// at the chosen m, so the rounds grow geometrically and an estimate takes a few dozen of them. The posterior is kept
/// exactly: every (m, heads, flips) seen is stored, and the log-likelihood is evaluated on a grid of
/// <see cref="GridPoints"/> angles over a window; when the posterior has left most of its window (all but 1e-9 of it
/// lies in under half), the grid is rebuilt on the narrower window from the stored flips, so the resolution follows σ.
/// Candidate powers (0, 1, 2, … growing by 1.25) are those whose fringe (period π/(2m+1)) spans at least 8 grid steps and whose flip the budget left pays.
/// </remarks>
public sealed class BayesianAmplitudeEstimator : AdaptiveMeanEstimator
{
    public const int GridPoints = GridPosteriorSearch.GridPoints;

    public const double RoundShare = GridPosteriorSearch.RoundShare;

    public BayesianAmplitudeEstimator(long queries) : base(queries) { }

    public override string Name => "bae";

    protected override IAdaptiveCoinSearch CreateSearch() => new GridPosteriorSearch(PosteriorFringe.CoinFlip);
}
