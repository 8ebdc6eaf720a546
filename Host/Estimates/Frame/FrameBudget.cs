namespace QuantumRayTracing.Estimates;

/// <summary>
/// How a frame's error budget is shared by its Grover runs. A frame fails when any of its R runs
/// fails, so by the union bound P(frame fails) ≤ Σ P(run i fails); giving every run the budget
/// <see cref="PerRun"/> = ε / R (and the Resource Estimator keeps each run's failure probability
/// within its budget) makes the frame fail with probability at most ε. <see cref="Frame"/> given to
/// every run alone is the other column: what each run would cost if the frame's budget were its own,
/// for a frame that may then fail with probability up to R · ε.
/// </summary>
/// <param name="Frame">ε, the largest probability that the whole frame fails; in (0, 1).</param>
/// <param name="Runs">R, the frame's Grover runs.</param>
public sealed record FrameBudget(double Frame, long Runs)
{
    /// <summary>The default frame budget: one frame in a hundred may fail.</summary>
    public const double DefaultFrame = 0.01;

    /// <summary>Why a budget is not usable, or null: it must lie strictly between 0 and 1.</summary>
    public static string? Problem(double budget) =>
        budget > 0 && budget < 1 ? null : $"must lie strictly between 0 and 1, got {budget.ToString(System.Globalization.CultureInfo.InvariantCulture)}";

    /// <summary>ε / R: each run's share under the union bound (ε when there are no runs).</summary>
    public double PerRun => Runs == 0 ? Frame : Frame / Runs;
}
