using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rendering;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What a soak renders: the engines, the seeds, the image sizes (<see cref="Size"/> for every engine but
/// the gate engine, which simulates every comparator of its oracle and gets <see cref="GateSize"/>), the
/// TracePass and DirectPass rounds, the area samples and VPLs, and how the two Q# simulator engines are
/// kept to a bounded time: the gate engine by <see cref="GateBudget"/>, and in the short form (<see
/// cref="SimulatorsOnSmallestSceneOnly"/>) both of them only on the scene with the fewest primitives. The two
/// run on <see cref="Pool"/>'s bridges when given (a cluster), else on <see cref="Workers"/> local ones.
/// Everything else is `render`'s default pipeline (<see cref="RenderDefaults"/>) without the accuracy budget, which settles every ray of
/// the smallest scenes classically and would leave a seed nothing to change.
/// </summary>
public sealed record SoakSettings(
    IReadOnlyList<EngineKind> Engines,
    IReadOnlyList<ulong> Seeds,
    int Size,
    int GateSize,
    int Iterations,
    int ShadowIterations,
    int AreaSamples,
    int Vpl,
    TimeSpan GateBudget,
    bool SimulatorsOnSmallestSceneOnly,
    int Workers,
    int MaxQubits = GateEngine.DefaultMaxQubits,
    BridgePool? Pool = null)
{
    /// <summary>Every engine, in the order the report lists them: the reference first, the simulators last.</summary>
    public static readonly EngineKind[] AllEngines =
        [EngineKind.Classical, EngineKind.Randomized, EngineKind.Analytic, EngineKind.FullState, EngineKind.Gate];

    public static readonly ulong[] DefaultSeeds = [1, 2];

    /// <summary>16x16: every pass and the lattice's four levels have work, and fullstate stays near 15 s a render.</summary>
    public const int DefaultSize = 16;

    /// <summary>4x4: the gate engine costs tens of milliseconds per Grover iteration at N = 64 (docs/render-results.md).</summary>
    public const int DefaultGateSize = 4;

    /// <summary>
    /// A gate render forecast (<see cref="GateCostEstimate"/>) to take longer than this is skipped. The forecast
    /// runs high (qornell-64 at 4x4: 8 s forecast, 10 s measured; qornell-128: 71 s, 26 s; the area-light
    /// scene: 138 s, 38 s), so 5 minutes admits every shipped scene up to N = 128 and keeps each render near a minute.
    /// </summary>
    public static readonly TimeSpan DefaultGateBudget = TimeSpan.FromMinutes(5);

    /// <summary>The full soak: `render`'s defaults at <see cref="DefaultSize"/> (the gate engine at <see cref="DefaultGateSize"/>).</summary>
    public static SoakSettings Full(int workers) => new(AllEngines, DefaultSeeds, DefaultSize, DefaultGateSize,
        RenderDefaults.Iterations, Passes.DirectPass.DefaultIterations, RenderDefaults.AreaSamples, RenderDefaults.Vpl,
        DefaultGateBudget, SimulatorsOnSmallestSceneOnly: false, workers);

    /// <summary>
    /// The CI form: 4x4 images (the gate engine 2x2), 2 TracePass rounds and 1 DirectPass round, 2 area
    /// samples, and the simulator engines only on the smallest scene; each of their renders costs seconds of
    /// bridge calls whatever the scene, the classical and analytic ones milliseconds.
    /// </summary>
    public static SoakSettings Short(int workers) => Full(workers) with
    {
        Size = 4,
        GateSize = 2,
        Iterations = 2,
        ShadowIterations = 1,
        AreaSamples = 2,
        SimulatorsOnSmallestSceneOnly = true,
    };

    /// <summary>The square image size <paramref name="kind"/> renders at.</summary>
    public int SizeFor(EngineKind kind) => kind.SimulatesOracleGates ? GateSize : Size;

    /// <summary>`render`'s default pipeline without the accuracy budget at <paramref name="size"/> with <paramref name="seed"/>, as `render --seed --budget 0` sets it.</summary>
    public RenderOptions Options(int size, ulong seed) => RenderDefaults.Options(size, size, seed) with
    {
        Iterations = Iterations, ShadowIterations = ShadowIterations, AreaSamples = AreaSamples, Vpl = Vpl, Budget = null,
    };
}
