using QuantumRayTracing.Metrics;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Benchmarks;

/// <summary>A pipeline configuration measured by <see cref="AccuracyBenchmark"/>: its options at a size, and its QSearch rule.</summary>
public sealed record AccuracyConfiguration(string Name, Func<int, ulong, RenderOptions> Options, QSearchOptions QSearch);

/// <summary>
/// One cell of the accuracy table: a configuration on one scene kind at one size, over several seeds.
/// Wrong pixels are those whose 8-bit RGB differs from the classical render of the same scene and size;
/// <see cref="AllowedWrong"/> sums the expected wrong pixels each render's configuration allows.
/// </summary>
public sealed record AccuracyCell(
    RandomSceneKind Kind, int Size, string Configuration, int Seeds, long Pixels, long WrongPixels, double AllowedWrong,
    long IntersectionsConservative, long Rays)
{
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
    /// <summary>Our default, the default without the lattice, and the paper's plain pipeline (4 rounds, 2 shadow rounds, no optimisation, its M sets).</summary>
    public static IReadOnlyList<AccuracyConfiguration> Standard { get; } =
    [
        new("default", (size, seed) => RenderDefaults.Options(size, size, seed), new QSearchOptions()),
        new("--lattice 0", (size, seed) => RenderDefaults.Options(size, size, seed) with { LatticeLevels = 0 }, new QSearchOptions()),
        new("paper, plain", (size, seed) => new RenderOptions(size, size, Seed: seed), new QSearchOptions(Rule: MSetRule.Round)),
    ];

    public static IReadOnlyList<AccuracyCell> Measure(
        RandomSceneKind kind, int size, IReadOnlyList<ulong> seeds, IReadOnlyList<AccuracyConfiguration> configurations)
    {
        var cells = configurations.Select(c => new AccuracyCell(kind, size, c.Name, 0, 0, 0, 0, 0, 0)).ToArray();
        foreach (var seed in seeds)
        {
            var scene = RandomScene.Build(kind, seed);
            using var classical = new ClassicalHitSearch();
            var reference = SceneRenderer.Render(scene, classical, RenderDefaults.Reference(new RenderOptions(size, size, Seed: seed)));
            for (var c = 0; c < configurations.Count; c++)
            {
                var options = configurations[c].Options(size, seed);
                using var search = Cli.EngineOptions.CreateHitSearch(Engines.EngineKind.Analytic, new SeededRandom(seed), 1, configurations[c].QSearch);
                var result = SceneRenderer.Render(scene, search, options);
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
                };
            }
        }
        return cells;
    }
}
