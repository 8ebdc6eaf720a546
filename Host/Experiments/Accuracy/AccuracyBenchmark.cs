using QuantumRayTracing.Metrics;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>A pipeline configuration measured by <see cref="AccuracyBenchmark"/>: its options at a size, and its QSearch rule.</summary>
public sealed record AccuracyConfiguration(string Name, Func<int, ulong, RenderOptions> Options, QSearchOptions QSearch);

/// <summary>
/// One cell of the accuracy table: a configuration on one scene kind at one size, over several seeds.
/// Wrong pixels are those whose 8-bit RGB differs from the classical render of the same scene and size;
/// <see cref="AllowedWrong"/> sums the expected wrong pixels each render printed.
/// </summary>
public sealed record AccuracyCell(
    RandomSceneKind Kind, int Size, string Configuration, int Seeds, long Pixels, long WrongPixels, double AllowedWrong,
    long IntersectionsConservative, long Rays)
{
    /// <summary>Rays settled classically, over the seeds.</summary>
    public long SettledRays { get; init; }

    /// <summary>Renders whose expectation stayed above their budget.</summary>
    public int OverBudget { get; init; }

    public double WrongShare => (double)WrongPixels / Pixels;

    public double IntPerRay => Rays == 0 ? 0 : (double)IntersectionsConservative / Rays;
}

/// <summary>
/// The default pipeline's accuracy on scenes it was not tuned on: random scenes of every
/// <see cref="RandomSceneKind"/>, rendered on the analytic engine at several sizes and seeds by several
/// configurations, each compared pixel by pixel with the classical render.
/// </summary>
public static class AccuracyBenchmark
{
    /// <summary>
    /// Our default, the same without the budget's rounds and classical settle (its searches as configured: the cost the
    /// budget adds), the default without the lattice, and the paper's plain pipeline (4 rounds, 2 shadow rounds, no
    /// optimisation, its M sets).
    /// </summary>
    public static IReadOnlyList<AccuracyConfiguration> Standard { get; } =
    [
        new("default", (size, seed) => RenderDefaults.Options(size, size, seed), new QSearchOptions()),
        new("no budget", (size, seed) => RenderDefaults.Options(size, size, seed) with { Budget = null }, new QSearchOptions()),
        new("--lattice 0", (size, seed) => RenderDefaults.Options(size, size, seed) with { LatticeLevels = 0 }, new QSearchOptions()),
        new("paper, plain", (size, seed) => RenderOptions.PaperPipeline(size, size, seed), new QSearchOptions(Rule: MSetRule.Round)),
    ];

    /// <summary>
    /// The ways to keep the budget measured against each other: the default (budget rounds after the passes, the paper's
    /// stop rule of one miss, each lattice level's cheap confirmation sized by the budget), two required misses before the
    /// rounds, the fixed cheap confirmation missing at most 40 % at every level (`--agreed-miss 0.4`), and one lattice level more.
    /// </summary>
    public static IReadOnlyList<AccuracyConfiguration> Alternatives { get; } =
    [
        Standard[0],
        new("2 required misses", (size, seed) => RenderDefaults.Options(size, size, seed) with { RequiredMisses = 2 }, new QSearchOptions()),
        new("--agreed-miss 0.4", (size, seed) => RenderDefaults.Options(size, size, seed) with { SizeConfirmation = false }, new QSearchOptions()),
        new("one lattice level more", (size, seed) => RenderDefaults.Options(size, size, seed) with
        {
            LatticeLevels = Math.Min(RenderDefaults.LatticeLevels, RenderDefaults.LatticeLevelsFor(size, size) + 1),
        }, new QSearchOptions()),
    ];

    public static IReadOnlyList<AccuracyCell> Measure(
        RandomSceneKind kind, int size, IReadOnlyList<ulong> seeds, IReadOnlyList<AccuracyConfiguration> configurations)
    {
        var cells = configurations.Select(c => new AccuracyCell(kind, size, c.Name, 0, 0, 0, 0, 0, 0)).ToArray();
        foreach (var seed in seeds)
        {
            var scene = RandomScene.Build(kind, seed);
            var reference = Renderer.Render(scene, new EngineSetup(EngineKind.Classical), RenderDefaults.Reference(RenderOptions.PaperPipeline(size, size, seed)));
            for (var c = 0; c < configurations.Count; c++)
            {
                var options = configurations[c].Options(size, seed);
                var result = Renderer.Render(scene, new EngineSetup(EngineKind.Analytic, configurations[c].QSearch), options);
                var error = ImageError.Between(result.Image, reference.Image);
                var total = result.Total;
                cells[c] = cells[c] with
                {
                    Seeds = cells[c].Seeds + 1,
                    Pixels = cells[c].Pixels + (long)size * size,
                    WrongPixels = cells[c].WrongPixels + error.DifferentPixels,
                    AllowedWrong = cells[c].AllowedWrong + result.Budget.ExpectedWrongPixels,
                    IntersectionsConservative = cells[c].IntersectionsConservative + total.IntersectionsConservative,
                    Rays = cells[c].Rays + total.Rays,
                    SettledRays = cells[c].SettledRays + total.SettledRays,
                    OverBudget = cells[c].OverBudget + (result.Budget.Exceeded ? 1 : 0),
                };
            }
        }
        return cells;
    }
}
