namespace QuantumRayTracing.Noise;

/// <summary>
/// Whose circuit the analytic engine's noise model counts: the gate-level oracle a machine would run (it computes
/// every intersection test in gates), or the lookup oracle, which marks indices from intersection answers computed
/// classically beforehand and so leaves out the cost, and the noise, of computing them.
/// </summary>
public enum NoiseOracle
{
    GateLevel,
    Lookup,
}

public static class NoiseOracles
{
    /// <summary>The name <c>--noise-oracle</c> takes and reports print.</summary>
    public static string Name(this NoiseOracle oracle) => oracle == NoiseOracle.GateLevel ? "gate-level" : "lookup";

    public static NoiseOracle? Parse(string text) => text switch
    {
        "gate-level" => NoiseOracle.GateLevel,
        "lookup" => NoiseOracle.Lookup,
        _ => null,
    };

    /// <summary>The oracle in words, beside every result under noise.</summary>
    public static string Description(this NoiseOracle oracle) => oracle == NoiseOracle.GateLevel
        ? "gate-level oracle (the circuit `qrt estimate` prices)"
        : "lookup oracle (intersections computed classically beforehand; their cost is left out)";
}
