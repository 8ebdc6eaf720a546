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
/// <param name="Options">QSearch's growth constant and M-set rule.</param>
/// <param name="Engine">The Grover engine (fullstate or analytic).</param>
/// <param name="Seed">The seed of every classical random choice.</param>
/// <param name="Workers">Local Node bridges the fullstate engine starts when <paramref name="Pool"/> is null; null: one per core.</param>
/// <param name="MaxQubits">The widest circuit the engine may simulate; null keeps the engine's own limit.</param>
/// <param name="Noise">The noise model the engine runs under; null for the ideal machine.</param>
/// <param name="Pool">Bridges the engine runs on (a cluster's, say), used and not stopped; null starts local ones.</param>
/// <param name="Device">A device noise model (gate rates by arity, readout error) instead of <paramref name="Noise"/>; null for none.</param>
public sealed record SearchRunSettings(
    int Count,
    IReadOnlyList<int>? Marked,
    int Searches,
    QSearchOptions Options,
    EngineKind Engine,
    ulong Seed,
    int? Workers = null,
    int? MaxQubits = null,
    NoiseModel? Noise = null,
    BridgePool? Pool = null,
    DeviceNoiseModel? Device = null)
{
    /// <summary>The marked set searched: the one given, or one index drawn from the seed's scenario stream.</summary>
    public MarkedSet MarkedSet => Marked is { } marked
        ? new MarkedSet(Count, marked)
        : new MarkedSet(Count, [new SeededRandom(Seed).Fork(RandomStreams.Scenario).NextInt(Count)]);

    public QSearchSchedule Schedule => new(Count, Options.Growth, Options.Rule);

    public SearchRegisters Registers => SearchRegisters.For(Count);

    public NoiseModel NoiseModel => Noise ?? NoiseModel.None;

    /// <summary>The noise model as this run's results name it.</summary>
    public string NoiseDescription => EngineFactory.NoiseDescription(Engine, NoiseModel, device: Device);

    /// <summary>The noise as `--json` records it.</summary>
    public Output.RunNoise RunNoise => Output.RunNoise.Of(Engine, NoiseModel, Device, NoiseDescription);

    public int LocalWorkers => Workers ?? BridgePool.DefaultWorkers;

    /// <summary>What is wrong with <paramref name="marked"/> as the marked indices of <paramref name="count"/>: one naming the first outside 0..N-1, or one listed twice; null if nothing.</summary>
    public static string? MarkedProblem(int count, IReadOnlyList<int> marked)
    {
        var outside = marked.Where(m => m < 0 || m >= count).Take(1).ToArray();
        if (outside.Length > 0) return $"--marked: index {outside[0]} is outside 0..{count - 1}";
        return marked.Distinct().Count() != marked.Count ? "--marked: an index is listed twice" : null;
    }
}
