namespace QuantumRayTracing.Estimation;

/// <summary>
/// Runs one adaptive search per item in lock step: each round gathers the next flips of every item still searching into
/// one engine batch. The coin is the mean coin of the item's subpixel values, its amplitudes times
/// the amplitude scale (½ gives head probability f/4, FAE's rescaled coin). No item spends more than
/// the budget queries: a search asking for more is a programming error and throws. A measure other than the coin flip (the
/// single-ancilla phase-estimation shot) takes each request's m and flips as its power and shots, at the same cost, 1 + 2m each.
/// </summary>
public static class AdaptiveFlips
{
    public static (double[] Estimates, QueryTally[] Spent) Run(IReadOnlyList<double[]> values, ICoinEngine engine,
        Func<IAdaptiveCoinSearch> create, long budget, double amplitudeScale = 1, Func<ICoinEngine, IReadOnlyList<CoinRequest>, IReadOnlyList<int>>? measure = null)
    {
        foreach (var v in values) CoinValues.Check(v);
        var amplitudes = values.Select(v => CoinValues.MeanCoin(v).Select(a => a * amplitudeScale).ToArray()).ToArray();
        var searches = values.Select(_ => create()).ToArray();
        var spent = new QueryTally[values.Count];
        var active = Enumerable.Range(0, values.Count).ToList();
        while (active.Count > 0)
        {
            var asked = new List<(int Item, CoinRequest Request)>();
            foreach (var j in active)
            {
                if (searches[j].Next(budget - spent[j].Queries) is not { } next) continue;
                var request = new CoinRequest(CoinKind.Mean, amplitudes[j], next.Iterations, next.Flips);
                if (next.Flips < 1 || next.Iterations < 0 || spent[j].Queries + request.Queries > budget)
                    throw new InvalidOperationException($"an adaptive search asked for {next.Flips} flips after {next.Iterations} Grover operators with {budget - spent[j].Queries} queries left");
                spent[j] = new QueryTally(spent[j].Queries + request.Queries, spent[j].GroverOperators + (long)next.Flips * next.Iterations);
                asked.Add((j, request));
            }
            if (asked.Count == 0) break;
            var heads = (measure ?? ((e, r) => e.FlipCoins(r)))(engine, asked.Select(a => a.Request).ToArray());
            for (var i = 0; i < asked.Count; i++) searches[asked[i].Item].Observe(heads[i]);
            active = asked.Select(a => a.Item).ToList();
        }
        return (searches.Select(s => Math.Clamp(s.Estimate(), 0, 1)).ToArray(), spent);
    }
}
