namespace QuantumRayTracing.Search;

/// <summary>
/// The seam the ray passes search through: a batch of ray searches in, one outcome per search out,
/// in order. The quantum engines answer with QSearch (<see cref="QuantumHitSearch"/>), the classical
/// ones by testing primitives directly; the passes above are the same for all.
/// </summary>
public interface IHitSearch : IDisposable
{
    /// <summary>The engine's name as chosen on the command line.</summary>
    string Name { get; }

    /// <summary>Runs every search; <paramref name="onRound"/> gets (round, searches still active) after each engine call.</summary>
    IReadOnlyList<HitOutcome> Run(IReadOnlyList<HitQuery> queries, Action<int, int>? onRound = null);
}
