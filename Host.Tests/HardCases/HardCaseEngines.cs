using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.HardCases;

/// <summary>
/// The engines every hard case runs on, by the name <c>--engine</c> gives them. The quantum ones come as a
/// Grover engine or as QSearch over it (<see cref="QuantumHitSearch"/>, gate-level requests for the gate
/// engine); the Q# ones share the collection's bridges, which the fixture owns.
/// </summary>
internal static class HardCaseEngines
{
    public const string Analytic = "analytic";
    public const string FullState = "fullstate";
    public const string Gate = "gate";
    public const string Classical = "classical";
    public const string Randomized = "randomized";

    /// <summary>A Grover engine; the analytic one seeded, so its checks are reproducible.</summary>
    public static IGroverEngine Grover(string name, FullStateFixture fixture, ulong seed) => name switch
    {
        Analytic => new AnalyticEngine(new SeededRandom(seed).Fork(RandomStreams.Engine)),
        FullState => new BorrowedEngine(fixture.Engine),
        Gate => new BorrowedEngine(new GateEngine(fixture.Engine.Pool)),
        _ => throw new ArgumentOutOfRangeException(nameof(name), name, "not a Grover engine"),
    };

    /// <summary>A ray search on any of the five engines, as the renderer builds it.</summary>
    public static IHitSearch Search(string name, FullStateFixture fixture, ulong seed) => name switch
    {
        Classical => new ClassicalHitSearch(),
        Randomized => new RandomizedHitSearch(new SeededRandom(seed)),
        _ => new QuantumHitSearch(Grover(name, fixture, seed), new SeededRandom(seed).Fork(RandomStreams.Search), new QSearchOptions(), gateLevel: name == Gate),
    };

    /// <summary>
    /// An engine on the fixture's bridges without their ownership: a search disposes its engine, which
    /// disposes its pool, and the fixture's bridges must outlive the test.
    /// </summary>
    private sealed class BorrowedEngine(IGroverEngine inner) : IGroverEngine
    {
        public string Name => inner.Name;

        public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests) => inner.Measure(requests);

        public void Dispose() { }
    }
}
