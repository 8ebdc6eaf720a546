using QuantumRayTracing.Cli;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Estimates;

/// <summary>
/// The frame recording renders the frame `render --engine analytic` renders, and records every Grover
/// run of it, each under the pass that made it.
/// </summary>
public sealed class FrameRecordingTests
{
    private static Scene Load(string name) => SceneLoader.Load(Path.Combine(RepositoryPaths.Scenes, name));

    [Theory]
    [InlineData("qornell-8.json", 8, 3UL)]
    [InlineData("qornell-64.json", 12, 5UL)]
    [InlineData("depth-complexity-32.json", 8, 1UL)]
    public void RecordsTheSameFrameAsTheAnalyticRenderAndEveryRunOfIt(string file, int size, ulong seed)
    {
        var scene = Load(file);
        var options = new RenderOptions(size, size, Seed: seed, Neighbours: true, ShadowNeighbours: true, Stop: StopMode.Exact, LatticeLevels: 2);
        var recording = FrameRecording.Record(scene, options, new QSearchOptions());

        // The render `render` makes: its own hit search, built the way the command builds it.
        using var search = EngineFactory.CreateSearch(EngineKind.Analytic, new SeededRandom(seed), 1, new QSearchOptions());
        var render = SceneRenderer.Render(scene, search, options);
        Assert.Equal(render.Image.Pixels.ToArray(), recording.Render.Image.Pixels.ToArray());

        // Each pass's Grover runs, as its own metrics count them, are the runs recorded under its name.
        Assert.NotEmpty(recording.Runs);
        foreach (var pass in render.Passes)
            Assert.True(pass.Cost.GroverRuns == recording.Runs.Count(r => r.Pass == pass.Name),
                $"{pass.Name}: {pass.Cost.GroverRuns} runs in the metrics, {recording.Runs.Count(r => r.Pass == pass.Name)} recorded");
        Assert.Equal(render.Total.Cost.QueriesPaper, recording.Runs.Sum(r => (long)r.Iterations));
        // Every run's shape has the example it will be priced on, with that shape.
        foreach (var run in recording.Runs) Assert.Equal(run.Shape, OracleShape.Of(recording.Examples[run.Shape]));
    }

    [Theory]
    [InlineData(0, 4, 0)]   // always holds
    [InlineData(16, 4, 5)]  // never holds: 2^w
    [InlineData(1, 4, 4)]   // odd: every bit compared
    [InlineData(8, 4, 1)]   // 1000: only the top bit
    [InlineData(12, 4, 2)]  // 1100
    public void ComparatorBitsCountTheBitsAboveTheTrailingZeros(long constant, int width, int expected) =>
        Assert.Equal(expected, OracleShape.ComparatorBits(constant, width));
}
