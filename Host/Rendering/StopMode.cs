namespace QuantumRayTracing.Rendering;

/// <summary>Whether and how rays stop early after empty searches (the paper's sec. 6.2).</summary>
public enum StopMode
{
    /// <summary>Every ray runs all its rounds.</summary>
    Off,

    /// <summary>p̄ from the paper's formula (eq. 10 at r = M_l, close to its table 6; eq. 11 for the randomized engine), t uniform on 1..N.</summary>
    Paper,

    /// <summary>p̄ the exact miss rate of our search, t uniform on 1..N.</summary>
    Exact,

    /// <summary>p̄ the exact miss rate for the distribution of t measured on the scene by a classical sample of primary rays.</summary>
    Scene,
}
