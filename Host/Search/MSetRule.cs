namespace QuantumRayTracing.Search;

/// <summary>How QSearch grows M_l, the upper bound of the random iteration count r_l.</summary>
public enum MSetRule
{
    /// <summary>Algorithm 1 as printed: M_l = min(ceil(c^l), ceil(sqrt N)) for l = 1, 2, … until M_l reaches ceil(sqrt N).</summary>
    Ceiling,

    /// <summary>The paper's table 6: M_l = round(c^l) for l = 0, 1, … while M_l &lt; ceil(sqrt N).</summary>
    Round,
}
