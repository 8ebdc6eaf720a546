using QuantumRayTracing.Estimates;
using QuantumRayTracing.Noise;

namespace QuantumRayTracing.Experiments;

/// <summary>Everything `bench noise` measured; the parts not asked for are empty.</summary>
public sealed record NoiseBenchResult(
    string Machine,
    TimeSpan Elapsed,
    IReadOnlyList<NoiseCheckRow> Check,
    IReadOnlyList<SupersamplingCheckRow> Supersampling,
    IReadOnlyList<NoiseBenchmark.DeviceRun> Device,
    CircuitCounts? DeviceSearch,
    CircuitCounts? DeviceOracle,
    IReadOnlyList<NoisyRenderBenchmark.Sweep> Sweeps,
    IReadOnlyList<(string Scene, double PerGate, RenderMeasurement Analytic, RenderMeasurement FullState)> Confirmations,
    IReadOnlyList<(string Key, string Scenes, GateLevelExposure Exposure)> Exposures,
    IReadOnlyList<NoiseCheckRow> Fit);
