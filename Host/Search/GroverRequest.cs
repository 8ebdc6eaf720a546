using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Search;

/// <summary>
/// One quantum step across the engine seam: prepare the uniform superposition over
/// <see cref="MarkedSet.Count"/> indices, apply <see cref="Iterations"/> Grover iterations with the
/// oracle marking <see cref="Marked"/>, measure the index register.
/// </summary>
public readonly record struct GroverRequest
{
    public GroverRequest(MarkedSet marked, int iterations, OracleInput? oracle = null)
    {
        ArgumentNullException.ThrowIfNull(marked);
        ArgumentOutOfRangeException.ThrowIfNegative(iterations);
        Marked = marked;
        Iterations = iterations;
        Oracle = oracle;
    }

    public MarkedSet Marked { get; }

    /// <summary>r ≥ 0; r = 0 samples the uniform superposition.</summary>
    public int Iterations { get; }

    /// <summary>
    /// For ray searches, what the gate-level oracle loads; <see cref="Marked"/> is then the set it
    /// marks, computed classically from the same table. Null for searches over a bare marked set.
    /// </summary>
    public OracleInput? Oracle { get; }
}
