namespace QuantumRayTracing.Search;

/// <summary>
/// One quantum step across the engine seam: prepare the uniform superposition over
/// <see cref="MarkedSet.Count"/> indices, apply <see cref="Iterations"/> Grover iterations with the
/// oracle marking <see cref="Marked"/>, measure the index register.
/// </summary>
public readonly record struct GroverRequest
{
    public GroverRequest(MarkedSet marked, int iterations)
    {
        ArgumentNullException.ThrowIfNull(marked);
        ArgumentOutOfRangeException.ThrowIfNegative(iterations);
        Marked = marked;
        Iterations = iterations;
    }

    public MarkedSet Marked { get; }

    /// <summary>r ≥ 0; r = 0 samples the uniform superposition.</summary>
    public int Iterations { get; }
}
