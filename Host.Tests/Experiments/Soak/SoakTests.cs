using QuantumRayTracing.Experiments;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>
/// `bench soak`: the short form over every shipped scene passes with every check run, and each check
/// fails when the fault it looks for is put in: a scene that does not load, an engine that throws, one
/// that renders a seed differently twice, one that ignores the seed, one that finds nothing, and the
/// gate engine's qubit limit and time budget, which skip rather than fail.
/// </summary>
public sealed class SoakTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-soak-");

    public void Dispose() => _scratch.Dispose();

    private static string Scene(string stem) => Path.Combine(RepositoryPaths.Scenes, stem + ".json");

    // qornell-8 has point lights only; qornell-64-area samples its area light, so its classical render depends on the seed.
    private static readonly string[] TwoScenes = [Scene("qornell-8"), Scene("qornell-64-area")];

    private static SoakSettings Seedable => SoakSettings.Short(2) with { Engines = [EngineKind.Classical, EngineKind.Randomized, EngineKind.Analytic] };

    private static IReadOnlyList<SoakRow> Run(IReadOnlyList<string> files, SoakSettings settings, Func<EngineKind, ulong, IHitSearch>? searches = null)
    {
        using var engines = new SoakEngines(settings.Workers, settings.MaxQubits);
        return Soak.Run(files, settings, searches is null ? engines.Render : (scene, kind, options, progress) =>
        {
            using var search = searches(kind, options.Seed);
            return SceneRenderer.Render(scene, search, options, progress);
        });
    }

    private static SoakRow Row(IReadOnlyList<SoakRow> rows, string scene, EngineKind kind) =>
        Assert.Single(rows, r => r.Scene == scene && r.Engine == kind);

    [Fact]
    public void ShortFormPassesOnEveryShippedSceneAndRunsEveryCheck()
    {
        var files = Directory.GetFiles(RepositoryPaths.Scenes, "*.json");
        var rows = Run(files, SoakSettings.Short(2));

        Assert.Equal(files.Length * SoakSettings.AllEngines.Length, rows.Count);
        Assert.All(rows, r => Assert.NotEqual(SoakStatus.Failed, r.Status));
        foreach (var row in rows.Where(r => r.Engine!.Value.IsSeedable))
        {
            // Both seeds rendered twice and compared byte for byte; the seed's effect checked.
            Assert.Equal(SoakStatus.Ok, row.Status);
            Assert.Equal(4, row.Renders);
            Assert.True(row.Deterministic);
            Assert.NotNull(row.DifferentPixels);
        }
        Assert.All(rows.Where(r => r.Engine is EngineKind.Analytic or EngineKind.Randomized), r => Assert.NotEqual("none", r.SeedEffect));
        Assert.All(rows.Where(r => r.Engine == EngineKind.Classical), r => Assert.Equal(0, r.DifferentPixels));
        Assert.Equal("image", Row(rows, "qornell-64-area", EngineKind.Classical).SeedEffect);
        Assert.Equal("none", Row(rows, "qornell-8", EngineKind.Classical).SeedEffect);

        // The Q# engines ran on the smallest scene, once per seed, held to the pixel bound; elsewhere they are skipped.
        foreach (var kind in new[] { EngineKind.FullState, EngineKind.Gate })
        {
            var row = Row(rows, "qornell-8", kind);
            Assert.Equal(SoakStatus.Ok, row.Status);
            Assert.Equal(2, row.Renders);
            Assert.Null(row.Deterministic);
            Assert.NotNull(row.PixelBound);
            Assert.All(rows.Where(r => r.Engine == kind && r.Scene != "qornell-8"), r =>
            {
                Assert.Equal(SoakStatus.Skipped, r.Status);
                Assert.StartsWith("short form", r.Reason);
            });
        }
    }

    [Fact]
    public void AnEngineThatThrowsFailsItsRowOnly()
    {
        var rows = Run(TwoScenes, Seedable, (kind, seed) => kind == EngineKind.Randomized
            ? new Faulty(new ClassicalHitSearch(), _ => throw new InvalidOperationException("injected fault"))
            : EngineFactory.CreateSearch(kind, new SeededRandom(seed), 1, new QSearchOptions()));

        var failed = rows.Where(r => r.Status == SoakStatus.Failed).ToArray();
        Assert.Equal(2, failed.Length);
        Assert.All(failed, r =>
        {
            Assert.Equal(EngineKind.Randomized, r.Engine);
            Assert.Equal("seed 1: InvalidOperationException: injected fault", r.Reason);
            Assert.StartsWith("FAILED: ", r.StatusText);
        });
    }

    [Fact]
    public void ASeedRenderedTwiceDifferentlyIsNotDeterministic()
    {
        // Each render gets a fresh seed whatever it asked for, as an engine with a clock-seeded generator would.
        ulong renders = 100;
        var rows = Run([Scene("qornell-8")], Seedable with { Engines = [EngineKind.Analytic] },
            (kind, _) => EngineFactory.CreateSearch(kind, new SeededRandom(++renders), 1, new QSearchOptions()));

        var row = Assert.Single(rows);
        Assert.Equal(SoakStatus.Failed, row.Status);
        Assert.False(row.Deterministic);
        // Another image, or at least another search cost.
        Assert.Contains("seed 1: a second render ", row.Reason);
        Assert.Contains("seed 2: a second render ", row.Reason);
    }

    [Fact]
    public void AnEngineIgnoringTheSeedFails()
    {
        // Searches that use no randomness at all (the classical one, as if an engine had fallen back to it): on a
        // scene without sampled light nothing else the seed moves can change the render.
        var rows = Run([Scene("qornell-8")], Seedable with { Engines = [EngineKind.Analytic, EngineKind.Randomized] },
            (_, _) => new ClassicalHitSearch());

        Assert.Equal(2, rows.Count);
        Assert.All(rows, r =>
        {
            Assert.True(r.Deterministic);
            Assert.Equal(SoakStatus.Failed, r.Status);
            Assert.Equal("none", r.SeedEffect);
            Assert.Equal("every seed gives the same image and the same search cost: the seed is not used", r.Reason);
        });
    }

    [Fact]
    public void AClassicalEngineThatDependsOnTheSeedFails()
    {
        var rows = Run([Scene("qornell-8")], Seedable with { Engines = [EngineKind.Classical] },
            (_, seed) => EngineFactory.CreateSearch(EngineKind.Randomized, new SeededRandom(seed), 1, new QSearchOptions()));

        var row = Assert.Single(rows);
        Assert.Equal(SoakStatus.Failed, row.Status);
        Assert.Contains("pixels differ from the classical reference", row.Reason);
        Assert.Contains("although the scene samples no light", row.Reason);
    }

    [Fact]
    public void AQuantumEngineThatFindsNothingBreaksThePixelBound()
    {
        var rows = Run([Scene("qornell-8")], Seedable with { Engines = [EngineKind.Analytic], Size = 8 },
            (_, _) => new Faulty(new ClassicalHitSearch(), outcome => outcome with { Primitive = null, Certain = false }));

        var row = Assert.Single(rows);
        Assert.Equal(SoakStatus.Failed, row.Status);
        Assert.Equal(DifferentPixelBound.Max(64), row.PixelBound);
        Assert.True(row.DifferentPixels > row.PixelBound);
        Assert.Contains("over the bound of", row.Reason);
    }

    [Fact]
    public void TheGateEngineSkipsWhatItCannotHold()
    {
        // Refused before anything is simulated: no bridge starts.
        var narrow = Run([Scene("qornell-8")], SoakSettings.Short(2) with { Engines = [EngineKind.Gate], MaxQubits = 5 });
        var refused = Assert.Single(narrow);
        Assert.Equal(SoakStatus.Skipped, refused.Status);
        Assert.Matches(@"^needs \d+ qubits, over the limit of 5$", refused.Reason);

        var slow = Run([Scene("qornell-8")], SoakSettings.Short(2) with { Engines = [EngineKind.Gate], GateBudget = TimeSpan.Zero });
        Assert.StartsWith("forecast ", Assert.Single(slow).Reason);
        Assert.Equal(SoakStatus.Skipped, slow[0].Status);
    }

    [Fact]
    public void TheCommandWritesTheReportAndExitsNonZeroOnAFailure()
    {
        var scenes = Directory.CreateDirectory(_scratch.File("scenes")).FullName;
        File.Copy(Scene("qornell-8"), Path.Combine(scenes, "qornell-8.json"));
        string[] arguments = ["bench", "soak", "--short", "--engines", "classical,analytic", "--scenes", scenes, "-o", _scratch.File("soak.md")];

        Assert.Equal(0, ConsoleCaptureRun(arguments));
        var text = File.ReadAllText(_scratch.File("soak.md"));
        Assert.StartsWith(GeneratedReport.MarkdownMarker(BenchSoakCommand.CommandText), text);
        Assert.Contains("| qornell-8 | 8 | classical | 4x4 | 4 |", text);
        Assert.Contains("2 ok, 0 FAILED, 0 skipped", text);

        File.WriteAllText(Path.Combine(scenes, "broken.json"), "{ \"name\": ");
        Assert.Equal(ExitCodes.ChecksFailed, ConsoleCaptureRun(arguments));
        text = File.ReadAllText(_scratch.File("soak.md"));
        Assert.Contains("| broken |", text);
        Assert.Contains("FAILED: scene does not load: ", text);
        Assert.Contains("2 ok, 1 FAILED, 0 skipped", text);
    }

    [Fact]
    public void TheDefaultSceneDirectoryIsTheRepositorysScenes()
    {
        Assert.Equal(RepositoryPaths.Scenes, RepositoryScenes.Find(Path.Combine(RepositoryPaths.Root, "Host", "Cli")));
        Assert.Null(RepositoryScenes.Find(_scratch.Path));
    }

    [Fact]
    public void ThePixelBoundIsTheBinomialQuantile()
    {
        // P(Binomial(16, 0.1) > 9) ≈ 4.5e-7 ≤ 1e-6 < P(> 8) ≈ 5.9e-6; P(Binomial(256, 0.1) > 51) ≈ 6.4e-7 ≤ 1e-6 < P(> 50) ≈ 1.5e-6.
        Assert.Equal(9, DifferentPixelBound.Max(16));
        Assert.Equal(51, DifferentPixelBound.Max(256));
        Assert.Equal(4, DifferentPixelBound.Max(4));
        Assert.Equal(0, DifferentPixelBound.Max(100, rate: 0));
    }

    private static int ConsoleCaptureRun(string[] arguments) => Cli.ConsoleCapture.Run(arguments).Code;

    /// <summary>A search whose every outcome passes through <paramref name="change"/>.</summary>
    private sealed class Faulty(IHitSearch inner, Func<HitOutcome, HitOutcome> change) : IHitSearch
    {
        public string Name => inner.Name;

        public IReadOnlyList<HitOutcome> Run(IReadOnlyList<HitQuery> queries, Action<int, int>? onRound = null) =>
            inner.Run(queries, onRound).Select(change).ToArray();

        public double MissProbability(int count, IReadOnlyList<double> pt, bool paperFormula, QSearchSchedule? schedule = null) => 0.5;

        public double EmptySearchCost(int count, QSearchSchedule? schedule = null) => inner.EmptySearchCost(count, schedule);

        public void Dispose() => inner.Dispose();
    }
}
