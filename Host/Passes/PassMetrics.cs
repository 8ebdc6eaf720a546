using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// The paper's table 1 for one pass: rays traced, iterations (#It), oracle queries and classical tests
/// (in <see cref="Cost"/>), plus the lookup-table rows built (eval-rpc work, shown apart, never in
/// Int/Ray), #Cpix (rays whose result neighbour gathering changed) and wall time.
/// </summary>
public sealed record PassMetrics(string Name, long Rays, int Iterations, SearchCost Cost, long TableRows, TimeSpan Elapsed, long UpdatedPixels = 0)
{
    /// <summary>Rays settled classically (N tests each, in #C_Int) because their remaining quantum work was expected to cost more.</summary>
    public long SettledRays { get; init; }

    /// <summary>The rays the pass is expected to leave wrong on the machine it ran on (<see cref="RayLedger"/>).</summary>
    public double ExpectedWrong { get; init; }

    /// <summary>
    /// The rays the pass is expected to leave wrong as its plan sees them: <see cref="ExpectedWrong"/>, but for a noisy render
    /// planned with the ideal miss rates. What the later passes' share of the budget is reckoned from.
    /// </summary>
    public double PlannedWrong { get; init; }

    /// <summary>#Int (conservative) of the lattice's cheap confirmations, before any budget round.</summary>
    public long CheapIntersections { get; init; }

    /// <summary>#Int (conservative) of the budget rounds (<see cref="BudgetRounds"/>), their classical settles included.</summary>
    public long RoundIntersections { get; init; }

    /// <summary>#Int = #Eval + #C_Int, in the conservative query count.</summary>
    public long IntersectionsConservative => Cost.QueriesConservative + Cost.ClassicalTests;

    /// <summary>#Int = #Eval + #C_Int, in the paper's query count.</summary>
    public long IntersectionsPaper => Cost.QueriesPaper + Cost.ClassicalTests;

    public double PerRayConservative => Rays == 0 ? 0 : (double)IntersectionsConservative / Rays;

    public double PerRayPaper => Rays == 0 ? 0 : (double)IntersectionsPaper / Rays;

    /// <summary>
    /// One pass run in two phases over the same rays (lattice, then the rest) plus the classical work
    /// between them: rounds add up, the rays are counted once.
    /// </summary>
    public static PassMetrics Phases(PassMetrics first, PassMetrics second, long tests, long updated) => new(
        first.Name, first.Rays, first.Iterations + second.Iterations,
        first.Cost + second.Cost + new SearchCost(0, 0, tests, 0), first.TableRows + second.TableRows,
        first.Elapsed + second.Elapsed, first.UpdatedPixels + second.UpdatedPixels + updated)
    {
        SettledRays = first.SettledRays + second.SettledRays,
        ExpectedWrong = second.ExpectedWrong,
        PlannedWrong = second.PlannedWrong,
        CheapIntersections = first.CheapIntersections + second.CheapIntersections,
        RoundIntersections = first.RoundIntersections + second.RoundIntersections,
    };

    /// <summary>The metrics of several passes together; #It is the largest of theirs.</summary>
    public static PassMetrics Total(string name, IReadOnlyCollection<PassMetrics> passes) => new(
        name,
        passes.Sum(p => p.Rays),
        passes.Count == 0 ? 0 : passes.Max(p => p.Iterations),
        passes.Aggregate(default(SearchCost), (sum, p) => sum + p.Cost),
        passes.Sum(p => p.TableRows),
        TimeSpan.FromTicks(passes.Sum(p => p.Elapsed.Ticks)),
        passes.Sum(p => p.UpdatedPixels))
    {
        SettledRays = passes.Sum(p => p.SettledRays),
        ExpectedWrong = passes.Sum(p => p.ExpectedWrong),
        PlannedWrong = passes.Sum(p => p.PlannedWrong),
        CheapIntersections = passes.Sum(p => p.CheapIntersections),
        RoundIntersections = passes.Sum(p => p.RoundIntersections),
    };
}
