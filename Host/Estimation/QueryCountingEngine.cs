namespace QuantumRayTracing.Estimation;

/// <summary>
/// Passes every request through to another engine and counts what was asked for, in both conventions: queries (a flip 1,
/// a Grover operator 2, a QSS run 2^(t+1) − 1 per shot, a single-ancilla shot at power k 1 + 2k, docs/conventions.md) and Grover operators alone (the AE papers' oracle calls).
/// </summary>
public sealed class QueryCountingEngine(ICoinEngine inner) : ICoinEngine
{
    public string Name => inner.Name;

    /// <summary>Queries asked for so far.</summary>
    public long Queries { get; private set; }

    /// <summary>Grover operators asked for so far.</summary>
    public long GroverOperators { get; private set; }

    public IReadOnlyList<int> FlipCoins(IReadOnlyList<CoinRequest> requests)
    {
        foreach (var r in requests) (Queries, GroverOperators) = (Queries + r.Queries, GroverOperators + (long)r.Flips * r.Iterations);
        return inner.FlipCoins(requests);
    }

    public IReadOnlyList<int[]> ReadCounters(IReadOnlyList<QssRequest> requests)
    {
        foreach (var r in requests)
        {
            var operators = (1L << r.CounterBits) - 1;
            (Queries, GroverOperators) = (Queries + r.Shots * (1 + 2 * operators), GroverOperators + r.Shots * operators);
        }
        return inner.ReadCounters(requests);
    }

    public IReadOnlyList<int> CountAncillaZeros(IReadOnlyList<AncillaPhaseRequest> requests)
    {
        foreach (var r in requests) (Queries, GroverOperators) = (Queries + r.Queries, GroverOperators + (long)r.Shots * r.Power);
        return inner.CountAncillaZeros(requests);
    }

    public void Dispose() => inner.Dispose();
}
