namespace QuantumRayTracing.Engines;

/// <summary>The engines a user can choose with --engine.</summary>
public enum EngineKind
{
    /// <summary>The Q# operations on the QDK full-state simulator, through the Node bridge.</summary>
    FullState,

    /// <summary>Exact closed-form outcome distributions, sampled in C#.</summary>
    Analytic,
}
