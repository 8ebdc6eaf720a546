using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// Every Grover run one frame asks for: the frame is rendered exactly as `render --engine analytic`
/// renders it (same scene, options and seed, so the same searches and the same image), with a
/// <see cref="RecordingEngine"/> at the engine seam noting each request's oracle shape and r.
/// </summary>
/// <param name="Render">The analytic render itself.</param>
/// <param name="Runs">Every run in the order it was asked for.</param>
/// <param name="Examples">For each shape, the first oracle input that had it: the circuit the shape's price is estimated on.</param>
public sealed record FrameRecording(RenderResult Render, IReadOnlyList<RecordedRun> Runs, IReadOnlyDictionary<OracleShape, OracleInput> Examples)
{
    /// <summary>The pass names in render order, as the render's metrics list them.</summary>
    public IReadOnlyList<string> Passes => Render.Passes.Select(p => p.Name).Distinct().ToArray();

    public static FrameRecording Record(Scene scene, RenderOptions options, QSearchOptions search, IRenderProgress? progress = null)
    {
        var recorder = new Recorder(progress);
        var root = new SeededRandom(options.Seed);
        // The analytic hit search `render` builds (EngineFactory.CreateSearch), with the recorder at its seam and the
        // oracle inputs attached (gate level), which the analytic engine ignores: the same draws, the same image.
        var engine = new RecordingEngine(new AnalyticEngine(root.Fork(RandomStreams.Engine)), recorder.Listen);
        RenderResult render;
        using (var hitSearch = new QuantumHitSearch(engine, root.Fork(RandomStreams.Search), search, gateLevel: true))
            render = SceneRenderer.Render(scene, hitSearch, options, recorder);
        return new FrameRecording(render, recorder.Finish(), recorder.Examples);
    }

    /// <summary>
    /// Collects runs batch by batch. A pass reports progress after each block of its searches, so the
    /// runs recorded since the last report belong to the stage that reports next.
    /// </summary>
    private sealed class Recorder(IRenderProgress? inner) : IRenderProgress
    {
        private readonly List<RecordedRun> _runs = [];
        private readonly List<(int Batch, OracleShape Shape, int Iterations)> _pending = [];
        private readonly Dictionary<OracleShape, OracleInput> _examples = [];
        private int _batches;

        public IReadOnlyDictionary<OracleShape, OracleInput> Examples => _examples;

        public void Listen(IReadOnlyList<GroverRequest> requests)
        {
            var batch = _batches++;
            foreach (var request in requests)
            {
                var input = request.Oracle ?? throw new InvalidOperationException("a ray search reached the seam without its oracle input");
                var shape = OracleShape.Of(input);
                _examples.TryAdd(shape, input);
                _pending.Add((batch, shape, request.Iterations));
            }
        }

        public void Report(string stage, double done)
        {
            foreach (var (batch, shape, iterations) in _pending) _runs.Add(new RecordedRun(stage, batch, shape, iterations));
            _pending.Clear();
            inner?.Report(stage, done);
        }

        public IReadOnlyList<RecordedRun> Finish() => _pending.Count == 0
            ? _runs
            : throw new InvalidOperationException($"{_pending.Count} Grover runs were recorded after the last pass reported");
    }
}
