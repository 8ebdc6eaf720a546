namespace QuantumRayTracing.Search;

/// <summary>
/// The sequence M_1, M_2, … of QSearch's iteration bounds for one N, computed once and shared by
/// every search over N indices.
/// </summary>
public sealed class QSearchSchedule
{
    public const double DefaultGrowth = 1.8;

    private readonly int[] _bounds;

    public QSearchSchedule(int count, double growth = DefaultGrowth, MSetRule rule = MSetRule.Ceiling)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(count, 1);
        if (!(growth > 1.0 && growth < 2.0))
            throw new ArgumentOutOfRangeException(nameof(growth), growth, "the growth constant c must satisfy 1 < c < 2");
        Count = count;
        Growth = growth;
        Rule = rule;
        _bounds = rule switch
        {
            MSetRule.Ceiling => CeilingBounds(CeilSqrt(count), growth),
            MSetRule.Round => RoundBounds(CeilSqrt(count), growth),
            _ => throw new ArgumentOutOfRangeException(nameof(rule), rule, null),
        };
    }

    public int Count { get; }
    public double Growth { get; }
    public MSetRule Rule { get; }

    /// <summary>M_1, M_2, …: one Grover run per bound after the initial sample.</summary>
    public IReadOnlyList<int> Bounds => _bounds;

    /// <summary>Smallest k with k² ≥ n, in integers.</summary>
    public static int CeilSqrt(int n)
    {
        var k = (int)Math.Sqrt(n);
        while ((long)k * k < n) k++;
        while (k > 0 && (long)(k - 1) * (k - 1) >= n) k--;
        return k;
    }

    private static int[] CeilingBounds(int cap, double growth)
    {
        var bounds = new List<int>();
        var power = 1.0;
        for (var m = 0; m < cap;)
        {
            power *= growth;
            m = (int)Math.Min(Math.Ceiling(power), cap);
            bounds.Add(m);
        }
        return [.. bounds];
    }

    private static int[] RoundBounds(int cap, double growth)
    {
        var bounds = new List<int>();
        for (var power = 1.0; ; power *= growth)
        {
            var m = (int)Math.Round(power, MidpointRounding.AwayFromZero);
            if (m >= cap) break;
            bounds.Add(m);
        }
        return [.. bounds];
    }
}
