namespace QuantumRayTracing.Search;

/// <summary>
/// The sequence M_1, M_2, … of QSearch's iteration bounds for one N, computed once and shared by
/// every search over N indices. A <see cref="Fixed"/> schedule instead lists the iteration counts
/// themselves, run in order without the initial sample: a confirmation tuned to the t a scene has.
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

    private QSearchSchedule(int count, int[] iterations)
    {
        Count = count;
        IsFixed = true;
        _bounds = iterations;
    }

    /// <summary>A schedule that runs exactly <paramref name="iterations"/>, in order, with no initial sample.</summary>
    public static QSearchSchedule Fixed(int count, IReadOnlyList<int> iterations)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(count, 1);
        if (iterations.Count == 0 || iterations.Any(r => r < 1))
            throw new ArgumentException("a fixed schedule lists at least one iteration count, each at least 1", nameof(iterations));
        return new QSearchSchedule(count, [.. iterations]);
    }

    public int Count { get; }
    public double Growth { get; }
    public MSetRule Rule { get; }

    /// <summary>Whether <see cref="Bounds"/> are the iteration counts themselves (see <see cref="Fixed"/>).</summary>
    public bool IsFixed { get; }

    /// <summary>M_1, M_2, …: one Grover run per bound after the initial sample; for a fixed schedule, the runs' iteration counts.</summary>
    public IReadOnlyList<int> Bounds => _bounds;

    public override string ToString() => IsFixed ? $"r = {string.Join(", ", _bounds)}" : $"M = {{{string.Join(", ", _bounds)}}}";

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
