using System.CommandLine;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Cli;

/// <summary>
/// How a frame is rendered beyond its scene, size and seed: passes, tie-breaking, neighbours,
/// termination, lattice, planned searches, light samples. `render` and `estimate --frame` share them,
/// so the same words give both the same frame.
/// </summary>
public sealed class RenderOptionSet
{
    public readonly Option<int> Passes = new Option<int>("--passes", "-p")
    {
        Description = "TracePass iterations (#IT) for primary and specular rays: searches for a closer hit per ray, at most (the stop rule ends most rays sooner).",
        DefaultValueFactory = _ => RenderDefaults.Iterations,
    }.Between(1, 64);

    public readonly Option<int> ShadowPasses = new Option<int>("--shadow-passes")
    {
        Description = "DirectPass rounds: QOccluded searches per shadow ray not yet found occluded.",
        DefaultValueFactory = _ => DirectPass.DefaultIterations,
    }.Between(1, 64);

    public readonly Option<TieBreak> TieBreak = new Option<TieBreak>("--tie-break")
    {
        Description = "Equal quantised depths: strict (the smaller primitive id wins, deterministic) or random (the paper: whichever is found first). The classical reference is always strict.",
        DefaultValueFactory = _ => Intersection.TieBreak.Strict,
        HelpName = "strict|random",
    }.Choices();

    public readonly Option<bool> Neighbours = new("--neighbours")
    {
        Description = "NeighOpt (Algorithm 5): after each round, test every primary and specular ray against the primitives its 4 neighbours hold (classical tests, counted in #C_Int; changed pixels in #Cpix).",
        DefaultValueFactory = _ => RenderDefaults.Neighbours,
    };

    public readonly Option<bool> ShadowNeighbours = new("--shadow-neighbours")
    {
        Description = "After each shadow round, test every unoccluded shadow ray against the occluders its neighbours' rays to the same light found.",
        DefaultValueFactory = _ => RenderDefaults.ShadowNeighbours,
    };

    public readonly Option<StopMode> Stop = new Option<StopMode>("--stop")
    {
        Description = "Termination criterion (sec. 6.2): after sn empty searches a ray is searched again with probability p̄^sn. off; paper (p̄ from eq. 10 at r = M_l / eq. 11, t uniform); exact (our search's exact miss rate, t uniform); scene (exact, for the t measured on a lattice of primary rays).",
        DefaultValueFactory = _ => RenderDefaults.Stop,
        HelpName = "off|paper|exact|scene",
    }.Choices();

    public readonly Option<int?> Lattice = new Option<int?>("--lattice")
    {
        Description = $"Lattice levels traced first (0: none). With L levels the pixels on the 2^L grid are searched first; then, level by level, every other ray tests its coarser neighbours' primitives (and shadow occluders) classically and gets one confirming search: cheap where all its neighbours agree, full where they disagree or some are missing. Applies to passes with --neighbours / --shadow-neighbours. Default: from the image size, as many levels (up to {RenderDefaults.LatticeLevels}) as keep {RenderDefaults.LatticePointsPerSide} lattice points along the shorter side.",
    }.Between(0, 6);

    public readonly Option<double> AgreedMiss = new Option<double>("--agreed-miss")
    {
        Description = $"Largest miss probability, for 1..{ConfirmationPlanner.MaxT} primitives left, of the cheap confirmation where lattice neighbours agree (the cheapest fixed list of Grover runs meeting it is used). Under the accuracy budget each lattice level's list is sized by the budget unless this option is given.",
        DefaultValueFactory = _ => RenderDefaults.AgreedMiss,
    }.StrictProbability();

    public readonly Option<double?> PlannedMiss = new Option<double?>("--planned-miss")
    {
        Description = $"Replace Algorithm 1's random schedule in every search (but the cheap confirmations) by the cheapest fixed list of Grover runs that misses at most this share of rays with 1..{ConfirmationPlanner.MaxT} hits. Default: Algorithm 1.",
        DefaultValueFactory = _ => RenderDefaults.PlannedMiss,
    }.StrictProbability();

    /// <summary>`render`'s accuracy budget; commands that price or plan a render rather than run it leave it out.</summary>
    public readonly Option<double> Budget = new Option<double>("--budget")
    {
        Description = "Accuracy budget: the share of pixels the render may leave wrong in expectation. The primary, specular and shadow passes search more where the expectation comes from until it is within, and settle classically a ray whose remaining quantum work would cost more than N tests. 0: no budget, the searches run as configured.",
        DefaultValueFactory = _ => AccuracyBudget.Target,
    }.Must(b => b is >= 0 and < 1 ? null : $"--budget must lie in [0, 1), got {b}");

    public readonly Option<int> AreaSamples = CommonOptions.AreaSamples("Shadow rays per surface point and area light (stratified, jittered; the paper: 32). Only scenes with area lights use it.");

    public readonly Option<int> Vpl = CommonOptions.Vpl("Virtual point lights per surface point for single-bounce indirect light: cosine-weighted rays traced to their closest hit, each lit by the scene's lights through shadow rays (0: no indirect light; the paper: 4).");

    /// <summary>Every option of the set, in help order.</summary>
    public IReadOnlyList<Option> All => [Passes, ShadowPasses, TieBreak, Neighbours, ShadowNeighbours, Stop, Lattice, AgreedMiss, PlannedMiss, AreaSamples, Vpl];

    public void AddTo(Command command) => command.AddOptions(All);

    public RenderOptions Get(ParseResult parse, int width, int height, ulong seed) => new(width, height, parse.GetValue(Passes), parse.GetValue(ShadowPasses),
        parse.GetValue(TieBreak), parse.GetValue(Neighbours), parse.GetValue(ShadowNeighbours), parse.GetValue(Stop), seed,
        parse.GetValue(Lattice) ?? RenderDefaults.LatticeLevelsFor(width, height), parse.GetValue(AgreedMiss), parse.GetValue(PlannedMiss),
        parse.GetValue(AreaSamples), parse.GetValue(Vpl), RequiredMisses: null, SizeConfirmation: parse.GetResult(AgreedMiss) is null or { Implicit: true });

    /// <summary>The accuracy budget `render` holds (its own option, not in <see cref="All"/>): null for --budget 0.</summary>
    public double? BudgetShare(ParseResult parse) => parse.GetValue(Budget) is > 0 and var budget ? budget : null;
}
