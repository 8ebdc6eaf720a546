using QuantumRayTracing.Bridge;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>
/// An engine as a render uses it: the kind, QSearch's options, the bridges a Q# engine runs on and the noise
/// it runs under. The seed is the render's (<see cref="Rendering.RenderOptions.Seed"/>).
/// </summary>
/// <param name="Kind">The engine.</param>
/// <param name="Search">QSearch's growth constant and M-set rule (the quantum engines).</param>
/// <param name="Workers">Local Node bridges a Q# engine starts when <paramref name="Pool"/> is null.</param>
/// <param name="MaxQubits">The widest circuit a Q# engine may simulate; null keeps the engine's own limit.</param>
/// <param name="Noise">The noise model of the quantum engines; null for the ideal machine.</param>
/// <param name="Pool">Bridges a Q# engine runs on (a cluster's, say), used and not stopped; null starts local ones.</param>
/// <param name="NoiseOracle">Whose circuit the analytic engine's noise model counts: the gate-level oracle by default.</param>
/// <param name="IdealPlan">Under noise, the passes plan with the noiseless machine's success probabilities (`render --ideal-plan`), not
/// the noisy ones they plan with by default; the expected wrong pixels they report still take the noisy ones (analytic engine).</param>
/// <param name="ImagePartsOnCluster">A seeded engine renders its image parts on the workers of <paramref name="Pool"/>'s cluster
/// (<see cref="Rendering.RemoteParts"/>; `render --cluster`); otherwise here, whatever pool its Q# counterparts are given.</param>
/// <param name="Device">A device noise model (gate rates by arity, readout error) instead of <paramref name="Noise"/>; null for none.</param>
public sealed record EngineSetup(
    EngineKind Kind,
    QSearchOptions Search,
    int Workers = 1,
    int? MaxQubits = null,
    NoiseModel? Noise = null,
    BridgePool? Pool = null,
    NoiseOracle NoiseOracle = NoiseOracle.GateLevel,
    bool IdealPlan = false,
    bool ImagePartsOnCluster = false,
    DeviceNoiseModel? Device = null)
{
    public EngineSetup(EngineKind kind) : this(kind, new QSearchOptions()) { }

    public NoiseModel NoiseModel => Noise ?? NoiseModel.None;

    /// <summary>
    /// This engine on <paramref name="bridges"/> (null: local bridges of its own); a seeded engine given a cluster's bridges renders
    /// its image parts on the cluster's workers (`render --cluster`).
    /// </summary>
    public EngineSetup OnBridges(BridgePool? bridges) =>
        this with { Pool = bridges, ImagePartsOnCluster = Kind.IsSeedable && bridges?.Remote is not null };

    /// <summary>The engine runs under some noise: a Pauli model or a device model.</summary>
    public bool IsNoisy => !NoiseModel.IsNoiseless || Device is { IsNoiseless: false };
}
