namespace QuantumRayTracing.Intersection;

/// <summary>How the closest hit is chosen among primitives at the same quantised depth.</summary>
public enum TieBreak
{
    /// <summary>The strict (depth, primitive id) order (docs/conventions.md): the smaller id wins. Deterministic.</summary>
    Strict,

    /// <summary>The paper's behaviour: only a strictly smaller depth replaces the current hit, so whichever equal-depth primitive is found first stays.</summary>
    Random,
}
