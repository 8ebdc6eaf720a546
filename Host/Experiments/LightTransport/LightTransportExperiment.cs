using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench light-transport`: the area light of each shading point estimated as the mean over its fixed sample set by Monte Carlo
/// and by each quantum estimator, at a range of queries per point and light over several seeds (analytic engine). Each render
/// gives its light error against the exact mean of each point's samples and its image error against the converged classical
/// reference; the fitted convergence lines, the queries to 1 % and images at equal queries make docs/light-transport.md.
/// </summary>
public static class LightTransportExperiment
{
    public const string Title = "Light transport: quantum light estimation against Monte Carlo";

    /// <summary>Monte Carlo first: the quantum estimators' spent queries are measured against its (it spends exactly its budget).</summary>
    public static readonly LightEstimator[] Estimators = [LightEstimator.Mc, LightEstimator.QCoin, LightEstimator.Mlae, LightEstimator.Iqae, LightEstimator.Bae];

    /// <summary>The report's plots and images at <paramref name="imageQueries"/>, by name, for checking their files before the work.</summary>
    public static string[] Pictures(IEnumerable<int> imageQueries) =>
        ["exact", "converged", "image-traced", "image-converged", .. imageQueries.SelectMany(q => new[] { $"image-{q}-mc", $"image-{q}-quantum" })];

    /// <summary>
    /// One render: its light NRMSE against the exact mean of each point's samples, its image NRMSE against the converged
    /// reference, and the queries it spent as a share of its budget (Monte Carlo's queries at the same seed and budget).
    /// </summary>
    public sealed record Cell(LightEstimator Estimator, int Queries, ulong Seed, double Exact, double Converged, double Spent);

    /// <summary>The classical render with every sample of each set traced: its image NRMSE against the converged reference, per seed.</summary>
    public sealed record Traced(ulong Seed, double Converged);

    /// <summary>Monte Carlo's and the best quantum estimator's render at <paramref name="Queries"/> each.</summary>
    public sealed record EqualQueries(int Queries, RenderResult Mc, RenderResult Quantum);

    /// <summary>Images at equal queries beside the exact means (every sample traced) and the converged reference.</summary>
    public sealed record Images(LightEstimator Best, IReadOnlyList<EqualQueries> Pairs, RgbImage Traced, RgbImage Converged);

    public static Report Run(LightTransportSettings settings, Action<string> progress)
    {
        var (cells, traced) = Measure(settings, progress);
        var fits = Estimators.ToDictionary(e => e, e => Fit(cells, e, c => c.Exact));
        var images = settings.ImageSize is { } size ? Render(settings, size, Best(fits), progress) : null;
        return LightTransportReport.Build(settings, cells, traced, fits, images);
    }

    /// <summary>Every estimator at every budget and seed, and the per-seed references.</summary>
    public static (IReadOnlyList<Cell> Cells, IReadOnlyList<Traced> Traced) Measure(LightTransportSettings settings, Action<string> progress)
    {
        var (scene, classical, analytic) = (settings.Scene, new EngineSetup(EngineKind.Classical), new EngineSetup(EngineKind.Analytic));
        var cells = new List<Cell>();
        var traced = new List<Traced>();
        for (var seed = 1UL; seed <= (ulong)settings.Seeds; seed++)
        {
            var options = Options(settings, settings.Size, seed);
            progress($"seed {seed}: references");
            var converged = Renderer.Render(scene, classical, RenderDefaults.Converged(options, settings.ReferenceSamples)).Image;
            var every = Renderer.Render(scene, classical, RenderDefaults.Reference(options)).Image;
            traced.Add(new Traced(seed, ImageError.Between(every, converged).Nrmse));
            foreach (var queries in settings.Queries)
            {
                long? budget = null;
                foreach (var estimator in Estimators)
                {
                    progress($"seed {seed}: {Name(estimator)} at {queries} queries");
                    var light = new LightEstimation(estimator, queries);
                    var result = Renderer.Render(scene, analytic, options with { Light = light });
                    var spent = result.Passes.Single(p => p.Name == AreaLightEstimatePass.Name(light)).Cost.QueriesConservative;
                    budget ??= spent;
                    cells.Add(new Cell(estimator, queries, seed, result.LightError!.Nrmse, ImageError.Between(result.Image, converged).Nrmse, (double)spent / budget.Value));
                }
            }
        }
        return (cells, traced);
    }

    /// <summary>The convergence line of <paramref name="estimator"/>'s <paramref name="error"/> over its seeds.</summary>
    public static ConvergenceFit? Fit(IEnumerable<Cell> cells, LightEstimator estimator, Func<Cell, double> error) =>
        ConvergenceFit.Of(cells.Where(c => c.Estimator == estimator).GroupBy(c => c.Seed).Select(seed => seed.Select(c => ((double)c.Queries, error(c)))));

    /// <summary>The quantum estimator that reaches 1 % with the fewest queries on its fitted line.</summary>
    public static LightEstimator Best(IReadOnlyDictionary<LightEstimator, ConvergenceFit?> fits) =>
        Estimators.Skip(1).MinBy(e => fits[e]?.QueriesTo(LightTransportReport.Target) ?? double.PositiveInfinity);

    public static string Name(LightEstimator estimator) => estimator.ToString().ToLowerInvariant();

    // `render`'s default pipeline with the bench's area samples.
    private static RenderOptions Options(LightTransportSettings settings, int size, ulong seed) =>
        RenderDefaults.Options(size, size, seed) with { AreaSamples = settings.AreaSamples };

    private static Images Render(LightTransportSettings settings, int size, LightEstimator best, Action<string> progress)
    {
        progress($"images at {size}x{size}");
        var (scene, classical, analytic) = (settings.Scene, new EngineSetup(EngineKind.Classical), new EngineSetup(EngineKind.Analytic));
        var options = Options(settings, size, 1);
        RenderResult At(LightEstimator estimator, int queries) => Renderer.Render(scene, analytic, options with { Light = new LightEstimation(estimator, queries) });
        return new Images(best, [.. settings.ImageQueries.Select(q => new EqualQueries(q, At(LightEstimator.Mc, q), At(best, q)))],
            Renderer.Render(scene, classical, RenderDefaults.Reference(options)).Image,
            Renderer.Render(scene, classical, RenderDefaults.Converged(options, settings.ReferenceSamples)).Image);
    }
}
