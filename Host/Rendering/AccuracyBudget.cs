using QuantumRayTracing.Passes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// The accuracy budget and the expected number of wrong pixels a render's configuration allows,
/// estimated from the miss rates of its search paths and how often each path found something. A ray
/// that still has a closer primitive to find is in an "episode" that ends either with a find or with
/// the ray stopped, wrong. On a path whose schedule misses with probability m (its worst exact miss for
/// t = 1..<see cref="RenderOptions.ConfirmationMaxT"/>, the t real scenes have) and which stops a ray after
/// s consecutive empty searches, an episode ends wrong with probability m^s, so each search that found
/// something stands for m^s / (1 − m^s) wrong ends. Two paths: the cheap confirmation of rays whose
/// lattice neighbours agree (s = 1), and the full search everywhere else (s = the stop rule's required
/// misses). It is an expectation, not a count, and errs high: every wrong ray is taken for a wrong
/// pixel, and neither neighbour gathering nor the extra rounds the stop rule may grant repair anything.
/// </summary>
public sealed record AccuracyBudget(double ExpectedWrongPixels, long Pixels)
{
    /// <summary>The share of pixels the default pipeline keeps wrong, in expectation, at any size and scene.</summary>
    public const double Target = 0.001;

    public double ExpectedShare => Pixels == 0 ? 0 : ExpectedWrongPixels / Pixels;

    /// <param name="passes">The render's passes, with their searches tallied by schedule.</param>
    /// <param name="search">The engine, for its schedules' exact miss rates (0 for the classical engines).</param>
    /// <param name="count">N, the scene's primitives.</param>
    /// <param name="cheap">The cheap confirmation's schedule, or null without a lattice.</param>
    /// <param name="requiredMisses">The stop rule's required misses for rays not vouched for (1 without termination).</param>
    /// <param name="pixels">The image's pixels.</param>
    public static AccuracyBudget From(IEnumerable<PassMetrics> passes, IHitSearch search, int count, QSearchSchedule? cheap, int requiredMisses, long pixels)
    {
        var expected = 0.0;
        foreach (var tally in SearchTally.Join(passes.SelectMany(p => p.Tallies)))
        {
            var s = tally.Schedule is not null && tally.Schedule == cheap ? 1 : requiredMisses;
            var wrongEnd = Math.Pow(WorstMiss(search, count, tally.Schedule), s);
            expected += wrongEnd >= 1 ? tally.Searches : tally.Found * wrongEnd / (1 - wrongEnd);
        }
        return new AccuracyBudget(expected, pixels);
    }

    /// <summary>
    /// The consecutive empty searches a ray with no agreeing lattice neighbours needs before the stop rule
    /// may end it: the fewest s with n · m^s ≤ half the budget's wrong pixels, n the rays of the coarsest
    /// lattice (every ray without a lattice), which have no neighbour to go by, and m the full search's worst
    /// miss for t ≤ <see cref="RenderOptions.ConfirmationMaxT"/>. A search that always answers (m = 0) needs one.
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

    /// <summary>The schedule's largest exact miss probability over t = 1..<see cref="RenderOptions.ConfirmationMaxT"/>.</summary>
    public static double WorstMiss(IHitSearch search, int count, QSearchSchedule? schedule)
    {
        var worst = 0.0;
        for (var t = 1; t <= Math.Min(count, RenderOptions.ConfirmationMaxT); t++)
        {
            var pt = new double[t + 1];
            pt[t] = 1;
            worst = Math.Max(worst, search.MissProbability(count, pt, paperFormula: false, schedule));
        }
        return worst;
    }
}
