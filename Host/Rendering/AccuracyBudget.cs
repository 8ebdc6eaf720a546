using QuantumRayTracing.Passes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// The accuracy budget and the expected number of wrong pixels a render leaves: the sum over its primary, specular
/// and shadow passes of each ray's probability of being wrong (<see cref="RayLedger"/>: from the worst miss rates of
/// its trailing empty searches and how often its path's searches found something). It is an expectation, not a
/// count, and errs high: every wrong ray is taken for a wrong pixel, and neighbour gathering repairs nothing. With a
/// budget the passes hold it (<see cref="BudgetRounds"/>): the primary pass may spend half, the specular pass a third of
/// what is left, the shadow pass the rest. Sampled light (area lights, VPLs) is not held to it: its Monte Carlo
/// estimate is compared with the converged reference instead.
/// </summary>
/// <param name="ExpectedWrongPixels">The expected wrong pixels.</param>
/// <param name="Pixels">The image's pixels.</param>
/// <param name="Share">The budget the render was held to (a share of pixels), or null when it had none.</param>
public sealed record AccuracyBudget(double ExpectedWrongPixels, long Pixels, double? Share = null)
{
    /// <summary>The share of pixels the default pipeline keeps wrong, in expectation, at any size and scene.</summary>
    public const double Target = 0.001;

    public double ExpectedShare => Pixels == 0 ? 0 : ExpectedWrongPixels / Pixels;

    /// <summary>The wrong pixels the budget allows, in expectation.</summary>
    public double Allowed => (Share ?? 0) * Pixels;

    /// <summary>Held to a budget and still above it: its passes ran out of budget rounds (<see cref="BudgetRounds.MaxRounds"/>).</summary>
    public bool Exceeded => Share is not null && ExpectedWrongPixels > Allowed * (1 + 1e-9);

    /// <summary>The expectation over the budgeted passes' metrics.</summary>
    /// <remarks>Capped at the pixels: a pass's expected wrong rays may exceed them (shadow rays, a noisy machine planned for as ideal), a pixel is wrong once.</remarks>
    public static AccuracyBudget From(IEnumerable<PassMetrics> budgeted, long pixels, double? share) =>
        new(Math.Min(pixels, budgeted.Sum(p => p.ExpectedWrong)), pixels, share);

    /// <summary>
    /// The consecutive empty searches a ray with no agreeing lattice neighbours needs before the stop rule
    /// may end it: the fewest s with n · m^s ≤ half the budget's wrong pixels, n the rays of the coarsest
    /// lattice (every ray without a lattice), which have no neighbour to go by, and m the full search's worst
    /// miss for t ≤ <see cref="ConfirmationPlanner.MaxT"/>. A search that always answers (m = 0) needs one.
    /// </summary>
    public static int RequiredMisses(double worstMiss, int width, int height, int latticeLevels)
    {
        var step = 1 << latticeLevels;
        var coarsest = (double)((width + step - 1) / step) * ((height + step - 1) / step);
        var allowed = Target / 2 * width * height;
        var required = 1;
        while (required < MaxRequiredMisses && coarsest * Math.Pow(worstMiss, required) > allowed) required++;
        return required;
    }

    /// <summary>The most consecutive empty searches the budget asks of a ray.</summary>
    public const int MaxRequiredMisses = 4;
}
