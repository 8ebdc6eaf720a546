namespace QuantumRayTracing.Search;

/// <summary>
/// Everything `search` prints about a run, in one record its text and its --json file are both written from:
/// the problem (N, the marked set, the bounds M_l, the registers), what was found, the total cost in both query
/// counts (docs/conventions.md) and per search, the engine calls and the wall time.
/// </summary>
public sealed record SearchFigures(
    int Count,
    IReadOnlyList<int> Marked,
    IReadOnlyList<int> Bounds,
    SearchRegisters Registers,
    int Searches,
    int Found,
    SearchCost Total,
    int Rounds,
    TimeSpan WallTime)
{
    public int NotFound => Searches - Found;

    public double QueriesConservativePerSearch => (double)Total.QueriesConservative / Searches;

    public double QueriesPaperPerSearch => (double)Total.QueriesPaper / Searches;

    public double ClassicalTestsPerSearch => (double)Total.ClassicalTests / Searches;

    public double GroverRunsPerSearch => (double)Total.GroverRuns / Searches;
}
