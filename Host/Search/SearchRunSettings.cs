using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Search;

/// <summary>
/// Everything one run of <see cref="SearchRun"/> needs: what `search` reads from its options.
/// </summary>
/// <param name="Count">N, the indices searched.</param>
/// <param name="Marked">The marked indices; null draws one index from the seed.</param>
/// <param name="Searches">Independent searches run side by side, one engine call per round for all of them.</param>
/// <param name="Engine">The Grover engine (fullstate or analytic), QSearch's growth constant and M-set rule, and the noise it runs under.</param>
/// <param name="Seed">The seed of every classical random choice.</param>
public sealed record SearchRunSettings(
    int Count,
    IReadOnlyList<int>? Marked,
    int Searches,
    EngineSetup Engine,
    ulong Seed)
{
    /// <summary>The marked set searched: the one given, or one index drawn from the seed's scenario stream.</summary>
    public MarkedSet MarkedSet => Marked is { } marked
        ? new MarkedSet(Count, marked)
        : new MarkedSet(Count, [new SeededRandom(Seed).Fork(RandomStreams.Scenario).NextInt(Count)]);

    public QSearchSchedule Schedule => new(Count, Engine.Search.Growth, Engine.Search.Rule);

    public SearchRegisters Registers => SearchRegisters.For(Count);

    /// <summary>The noise model as this run's results name it.</summary>
    public string NoiseDescription => EngineFactory.NoiseDescription(Engine.Kind, Engine.NoiseModel, device: Engine.Device);

    /// <summary>The noise as `--json` records it.</summary>
    public Output.RunNoise RunNoise => Output.RunNoise.Of(Engine.Kind, Engine.NoiseModel, Engine.Device, NoiseDescription);

    /// <summary>What is wrong with <paramref name="marked"/> as the marked indices of <paramref name="count"/>: one naming the first outside 0..N-1, or one listed twice; null if nothing.</summary>
    public static string? MarkedProblem(int count, IReadOnlyList<int> marked)
    {
        var outside = marked.Where(m => m < 0 || m >= count).Take(1).ToArray();
        if (outside.Length > 0) return $"--marked: index {outside[0]} is outside 0..{count - 1}";
        return marked.Distinct().Count() != marked.Count ? "--marked: an index is listed twice" : null;
    }
}
