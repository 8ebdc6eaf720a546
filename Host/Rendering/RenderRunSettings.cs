using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// Everything one run of <see cref="RenderRun"/> needs: what `render` reads from its options.
/// </summary>
/// <param name="Scene">The scene, loaded and checked.</param>
/// <param name="Options">Size, passes, pipeline and the seed of every classical random choice.</param>
/// <param name="Engine">Where the searches run.</param>
/// <param name="Search">QSearch's growth constant and M-set rule (the quantum engines).</param>
/// <param name="Output">The PNG the render is written to; the references and the difference image are written beside it.</param>
/// <param name="WithReference">Also write the classical reference, the difference image and, with sampled light, the converged reference.</param>
/// <param name="ReferenceSamples">Area samples and VPLs per point of the converged reference (sampled light only); 0 skips it.</param>
/// <param name="Workers">Local Node bridges a Q# engine starts when <paramref name="Pool"/> is null; null: one per core.</param>
/// <param name="MaxQubits">The widest circuit a Q# engine may simulate; null keeps the engine's own limit.</param>
/// <param name="Noise">The noise model the quantum engines run under; null for the ideal machine.</param>
/// <param name="Pool">Bridges a Q# engine runs on (a cluster's, say), used and not stopped; null starts local ones. A cluster's also renders a seeded engine's image parts (`render --cluster`).</param>
/// <param name="MaxMemory">The peak memory a large render may be forecast to need (<see cref="RenderForecast"/>); null: what the machine has available.</param>
/// <param name="NoiseOracle">Whose circuit the analytic engine's noise model counts.</param>
/// <param name="IdealPlan">Under noise, the passes plan with the noiseless machine's success probabilities instead of the noisy ones
/// (analytic engine); the expected wrong pixels are still computed with the noisy ones.</param>
/// <param name="Device">A device noise model (gate rates by arity, readout error) instead of <paramref name="Noise"/>; null for none.</param>
public sealed record RenderRunSettings(
    Scene Scene,
    RenderOptions Options,
    EngineKind Engine,
    QSearchOptions Search,
    string Output,
    bool WithReference = false,
    int ReferenceSamples = RenderDefaults.ReferenceSamples,
    int? Workers = null,
    int? MaxQubits = null,
    NoiseModel? Noise = null,
    BridgePool? Pool = null,
    long? MaxMemory = null,
    NoiseOracle NoiseOracle = NoiseOracle.GateLevel,
    bool IdealPlan = false,
    DeviceNoiseModel? Device = null)
{
    /// <summary>Area lights or VPLs: the render samples light, and a converged reference shows its Monte Carlo noise.</summary>
    public bool SamplesLight => RenderDefaults.SamplesLight(Scene, Options);

    /// <summary>The converged classical reference is rendered (and compared with).</summary>
    public bool WithConverged => SamplesLight && ReferenceSamples > 0;

    /// <summary>The options of the converged classical reference.</summary>
    public RenderOptions Converged => RenderDefaults.Converged(Options, Math.Max(1, ReferenceSamples));

    public NoiseModel NoiseModel => Noise ?? NoiseModel.None;

    /// <summary>The engine runs under some noise: a Pauli model or a device model.</summary>
    public bool IsNoisy => EngineSetup.IsNoisy;

    public int LocalWorkers => Workers ?? BridgePool.DefaultWorkers;

    /// <summary>The engine as <see cref="Renderer"/> builds it.</summary>
    public EngineSetup EngineSetup => new(Engine, Search, LocalWorkers, MaxQubits, NoiseModel, Pool, NoiseOracle, IdealPlan, ImagePartsOnCluster: Engine.IsSeedable && Pool?.Remote is not null, Device);

    /// <summary>The noise model as this run's results name it.</summary>
    public string NoiseDescription => EngineFactory.NoiseDescription(Engine, NoiseModel,
        Engine.ApproximatesNoise && IsNoisy ? EngineFactory.Approximation(NoiseOracle, Scene) : null, Device)
        + (!Engine.ApproximatesNoise || !IsNoisy ? ""
            : IdealPlan ? "; the passes plan with the ideal miss rates (--ideal-plan), the expected wrong pixels take the noisy ones"
            : "; the passes plan with the noisy runs' success");

    /// <summary>The noise as `--json` records it.</summary>
    public RunNoise RunNoise => RunNoise.Of(Engine, NoiseModel, Device, NoiseDescription);

    /// <summary>
    /// Refuses, before anything is printed or written, a noise model the engine cannot run, planning with a noise model the engine
    /// does not sample and an untraced circuit shape.
    /// </summary>
    public void EnsureRunnable()
    {
        EngineFactory.CheckNoise(Engine, NoiseModel, Device, Scene.Rectangles.Count);
        if (IdealPlan && !Engine.ApproximatesNoise) throw new UserError("--ideal-plan: only the analytic engine plans with a noise model; use --engine analytic");
        if (IdealPlan && !IsNoisy) throw new UserError("--ideal-plan: without a noise model (--noise, --device-noise, --readout-error) the plan is the ideal one already");
        if (Engine.ApproximatesNoise && IsNoisy) EngineFactory.Approximation(NoiseOracle, Scene);
    }

    /// <summary>Every PNG the run writes, in order: the render, then with <see cref="WithReference"/> the reference, the difference and the converged reference.</summary>
    public IReadOnlyList<string> Files => WithReference
        ? [Output, ImageFiles.Beside(Output, "reference"), ImageFiles.Beside(Output, "difference"), .. WithConverged ? [ImageFiles.Beside(Output, "converged")] : Array.Empty<string>()]
        : [Output];
}
