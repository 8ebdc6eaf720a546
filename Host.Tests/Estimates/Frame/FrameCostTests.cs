using QuantumRayTracing.Engines;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Estimates;

/// <summary>
/// A frame's cost against the per-run estimates summed by hand: on a 1x1 frame every Grover run is
/// estimated on its own ray's circuit (not through the shape cache), and the sums, maxima and the
/// failure bounds are taken here, apart from the frame code's aggregation.
/// </summary>
[Collection(QSharpCollection.Name)]
public sealed class FrameCostTests(FullStateFixture fixture)
{
    private const double Budget = 0.01;

    [Fact]
    public void FrameFiguresAreTheSumsOfThePerRunEstimatesAndTheSplitKeepsTheFrameWithinItsBudget()
    {
        var scene = SceneLoader.Load(Path.Combine(RepositoryPaths.Scenes, "qornell-8.json"));
        // One pixel: its primary and shadow rays' runs are of different circuits, so the sums are sums (checked below), and
        // each distinct circuit is one estimator job here (2x2 pixels gave four times the runs to price).
        var options = new RenderOptions(1, 1, Seed: 7);
        var search = new QSearchOptions();
        var models = QubitModel.Defaults;
        var frame = FrameEstimate.Run(new FrameSettings(scene, options, search, OracleConstruction.Default, models, Budget, Qpus: 1), fixture.Engine.Pool);

        // Every request of the same render, with its own oracle input, taken at the seam here.
        var requests = new List<GroverRequest>();
        var root = new SeededRandom(options.Seed);
        using (var hitSearch = new QuantumHitSearch(new RecordingEngine(new AnalyticEngine(root.Fork(RandomStreams.Engine)), requests.AddRange),
                   root.Fork(RandomStreams.Search), search, gateLevel: true))
            SceneRenderer.Render(scene, hitSearch, options);
        var quantum = requests.Where(r => r.Iterations > 0).ToArray();
        Assert.Equal(requests.Count, frame.Recording.Runs.Count);
        Assert.Equal(quantum.Length, frame.Cost.Budget.Runs);

        // Each run's own circuit, at ε / R and at ε; identical expressions are the same circuit, estimated once.
        var expressions = quantum.Select(r => EstimatedCircuits.SearchRun.Expression(new EstimateSubject(r.Oracle!, r.Iterations, ""))).ToArray();
        var distinct = expressions.Distinct().ToArray();
        Assert.True(distinct.Length >= 2, $"{quantum.Length} runs of {distinct.Length} distinct circuits: the sums would test nothing");
        // One estimator job per circuit prices it on every model at both budgets: the first models.Count physical
        // estimates at ε / R, the rest at ε.
        var estimator = new ResourceEstimator(fixture.Engine.Pool,
            [.. models.Select(m => m with { Budget = Budget / quantum.Length }), .. models.Select(m => m with { Budget = Budget })], withCircuits: false);
        var subjects = distinct.Select(e => quantum[Array.IndexOf(expressions, e)]).Select(r => (EstimatedCircuits.SearchRun, new EstimateSubject(r.Oracle!, r.Iterations, ""))).ToArray();
        var estimates = distinct.Zip(estimator.Estimate(subjects)).ToDictionary(p => p.First, p => p.Second);
        var split = estimates.ToDictionary(p => p.Key, p => p.Value with { Physical = p.Value.Physical.Take(models.Count).ToArray() });
        var alone = estimates.ToDictionary(p => p.Key, p => p.Value with { Physical = p.Value.Physical.Skip(models.Count).ToArray() });

        var total = frame.Cost.Total;
        var unsplit = new double[models.Count];
        Assert.Equal(expressions.Sum(e => split[e].Logical.Ccz), total.Logical.Ccz);
        Assert.Equal(expressions.Sum(e => split[e].Logical.T), total.Logical.T);
        Assert.Equal(expressions.Sum(e => split[e].Logical.Rotations), total.Logical.Rotations);
        Assert.Equal(expressions.Sum(e => split[e].Logical.Measurements), total.Logical.Measurements);
        Assert.Equal(expressions.Max(e => split[e].Logical.Qubits), total.Logical.Qubits);
        for (var m = 0; m < models.Count; m++)
        {
            var runs = expressions.Select(e => split[e].Physical[m]).ToArray();
            var figures = total.Split[m];
            Assert.Equal(runs.Max(p => p.PhysicalQubits), figures.PhysicalQubits);
            Assert.Equal(runs.Max(p => p.CodeDistance), figures.MaxCodeDistance);
            Assert.Equal(runs.Min(p => p.CodeDistance), figures.MinCodeDistance);
            Assert.Equal(runs.Sum(p => p.RuntimeNanoseconds), figures.SequentialNanoseconds, 1e-9 * figures.SequentialNanoseconds);
            Assert.Equal(figures.SequentialNanoseconds, figures.ParallelNanoseconds, 1e-9 * figures.SequentialNanoseconds); // one QPU
            Assert.Equal(expressions.Sum(e => alone[e].Physical[m].RuntimeNanoseconds), total.Alone[m].SequentialNanoseconds, 1e-9 * total.Alone[m].SequentialNanoseconds);

            // The frame fails only if a run does: Σ of the runs' failure bounds (from the estimator's own
            // error rates, depths and T states) bounds it. With ε / R per run it stays within ε; with ε
            // per run it need not (see below), so the split is what keeps the frame within its budget.
            var frameFailure = runs.Sum(p => p.Errors!.FailureBound);
            Assert.True(frameFailure <= Budget, $"{models[m]}: the runs' failure bounds sum to {frameFailure} > {Budget}");
            Assert.All(runs, p => Assert.True(p.Errors!.FailureBound <= Budget / quantum.Length * (1 + 1e-9), $"{models[m]}: a run's bound {p.Errors.FailureBound} exceeds its share"));
            Assert.Equal(frameFailure, figures.FailureBound, 1e-9 * frameFailure);
            unsplit[m] = expressions.Sum(e => alone[e].Physical[m].Errors!.FailureBound);
        }
        // On this frame ε per run would break the frame budget on some model (the gate-based one: its
        // runs use nearly all of their budget), so the checks above can fail.
        Assert.Contains(unsplit, u => u > Budget);
    }
}
