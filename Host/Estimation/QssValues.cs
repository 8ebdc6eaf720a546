namespace QuantumRayTracing.Estimation;

/// <summary>What QSS counts in a pixel.</summary>
public enum QssValues
{
    /// <summary>Bit planes (thesis 004 sec. 1.6): each plane a binary subpixel image read through the lookup table; gives a confidence map.</summary>
    Planes,

    /// <summary>The values themselves (paper 003 sec. 3.3): one run per channel, estimate sin²(πy/2^t).</summary>
    Continuous,
}
