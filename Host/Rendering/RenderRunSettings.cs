using QuantumRayTracing.Passes;
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
/// <param name="Engine">Where the searches run, under which noise and with which plan (<see cref="EngineSetup"/>).</param>
/// <param name="Output">The PNG the render is written to; the references and the difference image are written beside it.</param>
/// <param name="WithReference">Also write the classical reference, the difference image and, with sampled light, the converged reference.</param>
/// <param name="ReferenceSamples">Area samples and VPLs per point of the converged reference (sampled light only); 0 skips it.</param>
/// <param name="MaxMemory">The peak memory a large render may be forecast to need (<see cref="RenderForecast"/>); null: what the machine has available.</param>
public sealed record RenderRunSettings(
    Scene Scene,
    RenderOptions Options,
    EngineSetup Engine,
    string Output,
    bool WithReference = false,
    int ReferenceSamples = RenderDefaults.ReferenceSamples,
    long? MaxMemory = null)
{
    /// <summary>Area lights or VPLs: the render samples light, and a converged reference shows its Monte Carlo noise.</summary>
    public bool SamplesLight => RenderDefaults.SamplesLight(Scene, Options);

    /// <summary>The converged classical reference is rendered (and compared with).</summary>
    public bool WithConverged => SamplesLight && ReferenceSamples > 0;

    /// <summary>The options of the converged classical reference.</summary>
    public RenderOptions Converged => RenderDefaults.Converged(Options, Math.Max(1, ReferenceSamples));

    /// <summary>The engine runs under some noise: a Pauli model or a device model.</summary>
    public bool IsNoisy => Engine.IsNoisy;

    /// <summary>The noise model as this run's results name it.</summary>
    public string NoiseDescription => EngineFactory.NoiseDescription(Engine.Kind, Engine.NoiseModel,
        Engine.Kind.ApproximatesNoise && IsNoisy ? EngineFactory.Approximation(Engine.NoiseOracle, Scene) : null, Engine.Device)
        + (!Engine.Kind.ApproximatesNoise || !IsNoisy ? ""
            : Engine.IdealPlan ? "; the passes plan with the ideal miss rates (--ideal-plan), the expected wrong pixels take the noisy ones"
            : "; the passes plan with the noisy runs' success");

    /// <summary>The noise as `--json` records it.</summary>
    public RunNoise RunNoise => RunNoise.Of(Engine.Kind, Engine.NoiseModel, Engine.Device, NoiseDescription);

    /// <summary>
    /// Refuses, before anything is printed or written, a noise model the engine cannot run, planning with a noise model the engine
    /// does not sample and an untraced circuit shape.
    /// </summary>
    public void EnsureRunnable()
    {
        EngineFactory.CheckPrimitives(Engine.Kind, Scene);
        EngineFactory.CheckNoise(Engine.Kind, Engine.NoiseModel, Engine.Device, Scene.Primitives.Count);
        if (Engine.IdealPlan && !Engine.Kind.ApproximatesNoise) throw new UserError("--ideal-plan: only the analytic engine plans with a noise model; use --engine analytic");
        if (Engine.IdealPlan && !IsNoisy) throw new UserError("--ideal-plan: without a noise model (--noise, --device-noise, --readout-error) the plan is the ideal one already");
        if (Engine.Kind.ApproximatesNoise && IsNoisy) EngineFactory.Approximation(Engine.NoiseOracle, Scene);
        if (Options.Light is { } light) EnsureLightRunnable(light);
    }

    // One line for each setting light estimation cannot run with yet.
    private void EnsureLightRunnable(LightEstimation light)
    {
        var option = $"--light-estimator {light.Name}";
        if (Engine.Kind.RunsQSharp)
            throw new UserError($"{option}: the {Engine.Kind.Name} engine cannot run light estimation yet (its coin needs every sample's visibility over all primitives as a circuit); use --engine analytic");
        if (light.Estimator != LightEstimator.Mc && Engine.Kind != EngineKind.Analytic)
            throw new UserError($"{option}: a quantum estimator's outcomes are drawn from its exact distributions on the analytic engine only; use --engine analytic");
        if (IsNoisy) throw new UserError($"{option}: light estimation does not model noise yet; drop the noise model");
        if (Scene.AreaLights.Count == 0) throw new UserError($"{option}: {Scene.Name} has no area lights to estimate");
        // What VPL estimation lacks, so the refusal can say it: a coin per colour channel whose preparation traces the bounce and the VPL's shadow rays.
        if (Options.Vpl > 0)
            throw new UserError($"{option}: VPL light is not estimated yet (a VPL's contribution is a colour, its albedo times its own direct light, so it needs a coin per channel whose preparation finds the VPL's bounce hit and its shadow rays over all primitives, and no such coin exists); use --vpl 0, or --light-estimator mc without --light-queries to trace every VPL");
        if (!LightEstimation.IsRegisterSize(Options.AreaSamples))
            throw new UserError($"{option}: --area-samples {Options.AreaSamples} is not a power of two (the register a coin puts in superposition holds 2^k samples)");
    }

    /// <summary>Every PNG the run writes, in order: the render, then with <see cref="WithReference"/> the reference, the difference and the converged reference.</summary>
    public IReadOnlyList<string> Files => WithReference
        ? [Output, ImageFiles.Beside(Output, "reference"), ImageFiles.Beside(Output, "difference"), .. WithConverged ? [ImageFiles.Beside(Output, "converged")] : Array.Empty<string>()]
        : [Output];
}
