namespace QuantumRayTracing.Experiments;

/// <summary>
/// Published results of the ray tracing paper (000 in docs/conventions.md, tables 2 and 3; 128x128), the
/// numbers our tables are set against. Int/Ray there uses the paper's query count.
/// </summary>
public static class PaperNumbers
{
    /// <summary>Table 2: quantum Int/Ray, no optimisation, by scene file stem.</summary>
    public static readonly IReadOnlyDictionary<string, double> Scalability = new Dictionary<string, double>
    {
        ["qornell-8"] = 12.0,
        ["qornell-16"] = 18.0,
        ["qornell-32"] = 27.4,
        ["qornell-64"] = 33.6,
        ["qornell-128"] = 50.4,
        ["qornell-256"] = 51.3,
        ["qornell-512"] = 79.7,
        ["depth-complexity-32"] = 30.7,
        ["depth-complexity-64"] = 39.4,
    };

    /// <summary>Table 2's TracePass iterations: the Qornell rows equal table 3's 4-pass row, the Depth rows its 5-pass row.</summary>
    public static int ScalabilityIterations(string stem) => stem.StartsWith("depth", StringComparison.Ordinal) ? 5 : 4;

    /// <summary>Table 3 rows: (#It, Int/Ray, NRMSE, #Dpix) by scene file stem.</summary>
    public static readonly IReadOnlyDictionary<string, (int Iterations, double IntPerRay, double Nrmse, int DifferentPixels)[]> Iterations =
        new Dictionary<string, (int, double, double, int)[]>
        {
            ["qornell-64"] = [(1, 17.0, 0.63, 2278), (2, 22.6, 0.24, 430), (3, 28.1, 0.10, 146), (4, 33.6, 0.04, 107), (5, 39.2, 0.01, 103)],
            ["depth-complexity-64"] = [(1, 15.9, 0.34, 5665), (2, 21.7, 0.13, 2556), (3, 27.6, 0.04, 973), (4, 33.6, 0.01, 304), (5, 39.4, 0.00, 95), (6, 45.2, 0.00, 47)],
        };

    /// <summary>Table 6: p̄_QS for c = 1.8, by N.</summary>
    public static readonly IReadOnlyDictionary<int, double> Table6 = new Dictionary<int, double>
    {
        [8] = 0.205, [16] = 0.113, [32] = 0.055, [64] = 0.057, [128] = 0.029, [256] = 0.029, [512] = 0.015,
    };

    /// <summary>Table 7: optimised quantum (neighbours + termination) Int/Ray and #Dpix, by scene file stem.</summary>
    public static readonly IReadOnlyDictionary<string, (double IntPerRay, int DifferentPixels)> Optimised =
        new Dictionary<string, (double, int)>
        {
            ["qornell-8"] = (9.8, 11), ["qornell-16"] = (14.4, 89), ["qornell-32"] = (21.3, 92), ["qornell-64"] = (22.1, 103),
            ["qornell-128"] = (32.6, 108), ["qornell-256"] = (33.7, 144), ["qornell-512"] = (51.8, 124),
            ["depth-complexity-32"] = (22.0, 2), ["depth-complexity-64"] = (22.5, 21),
        };

    /// <summary>Table 8 (Qornell 64): Int/Ray and NRMSE of quantum (Q) and randomized classical (RC) per version.</summary>
    public static readonly IReadOnlyList<(string Version, double QIntPerRay, double QNrmse, double RcIntPerRay, double RcNrmse)> Randomized =
    [
        ("base", 33.6, 0.04, 33.5, 1.10),
        ("neighbours", 17.4, 0.003, 16.9, 0.076),
        ("neighbours + termination", 22.1, 0.004, 23.4, 0.075),
    ];

    /// <summary>Sec. 7: Int/Ray of the optimised quantum renderer and of the classical one, area light (Qornell 64, 32 samples) and VPL indirect light (temple, 32 primitives, 4 VPLs).</summary>
    public static readonly (double Quantum, double Classical) AreaLight = (21.8, 64);

    public static readonly (double Quantum, double Classical) IndirectLight = (22.4, 32);
}
