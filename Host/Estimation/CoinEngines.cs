using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Estimation;

/// <summary>The coin engine an engine kind runs mean estimation on, seeded from the run's engine stream.</summary>
public static class CoinEngines
{
    /// <remarks>
    /// The fullstate engine runs on <paramref name="pool"/> when given, without stopping it, else on bridges of its own. Under
    /// a <paramref name="device"/> model the coins are the single-qubit ones of the QCoin paper's device runs.
    /// </remarks>
    public static ICoinEngine Create(EngineKind kind, ulong seed, int workers, int? maxQubits = null, NoiseModel? noise = null, BridgePool? pool = null,
        DeviceNoiseModel? device = null)
    {
        var random = new SeededRandom(seed).Fork(RandomStreams.Engine);
        ICoinEngine engine = kind switch
        {
            EngineKind.FullState => new FullStateCoinEngine(pool ?? new BridgePool(workers), ownsPool: pool is null, maxQubits: maxQubits, noise: noise, device: device, readoutRandom: random),
            _ => new AnalyticCoinEngine(random, noise, device: device),
        };
        return device is null ? engine : new DirectCoinEngine(engine);
    }
}
