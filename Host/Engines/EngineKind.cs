namespace QuantumRayTracing.Engines;

/// <summary>The engines a user can choose with --engine.</summary>
public enum EngineKind
{
    /// <summary>The Q# operations on the QDK full-state simulator, through the Node bridge.</summary>
    FullState,

    /// <summary>The gate-level intersection oracle (paper sec. 4.2) on the QDK full-state simulator: exact and slow.</summary>
    Gate,

    /// <summary>Exact closed-form outcome distributions, sampled in C#.</summary>
    Analytic,

    /// <summary>Brute force: every ray tested against every primitive. The reference.</summary>
    Classical,

    /// <summary>A bounding-volume hierarchy (SAH build): the classical renderer with a spatial structure; certain, like brute force.</summary>
    Bvh,

    /// <summary>The paper's sec. 6.3: every ray tested against floor(sqrt N) random primitives.</summary>
    Randomized,
}
