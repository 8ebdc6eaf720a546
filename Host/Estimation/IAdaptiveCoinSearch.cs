namespace QuantumRayTracing.Estimation;

/// <summary>
/// One item's adaptive amplitude estimate: it asks for flips of the item's mean coin after m Grover operators, sees the
/// heads, and decides the next flips from them, until it stops and gives its estimate.
/// </summary>
public interface IAdaptiveCoinSearch
{
    /// <summary>The next flips (m Grover operators each, at least one flip), or null when the search is done.</summary>
    /// <param name="remaining">Queries left of the budget (a flip after m operators costs 1 + 2m).</param>
    (int Iterations, int Flips)? Next(long remaining);

    /// <summary>The heads of the flips <see cref="Next"/> asked for last.</summary>
    void Observe(int heads);

    /// <summary>The estimate of the mean in [0, 1].</summary>
    double Estimate();
}
