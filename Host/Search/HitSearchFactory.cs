using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Search;

/// <summary>The ray search of each engine: QSearch over a Grover engine (<see cref="EngineFactory"/>), or a classical search.</summary>
public static class HitSearchFactory
{
    public static IHitSearch Create(EngineKind kind, SeededRandom root, int workers, QSearchOptions options, int? maxQubits = null, BridgePool? pool = null, NoiseModel? noise = null)
    {
        EngineFactory.CheckNoise(kind, noise ?? NoiseModel.None);
        return kind switch
        {
            EngineKind.FullState or EngineKind.Analytic or EngineKind.Gate =>
                new QuantumHitSearch(EngineFactory.Create(kind, root, workers, maxQubits, pool, noise), root.Fork(RandomStreams.Search), options, gateLevel: kind == EngineKind.Gate),
            EngineKind.Classical => new ClassicalHitSearch(),
            EngineKind.Randomized => new RandomizedHitSearch(root.Fork(RandomStreams.Engine)),
            _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, null),
        };
    }
}
