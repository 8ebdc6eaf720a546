using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>
/// The engine seam: a batch of Grover requests in, one measured index per request out, in order.
/// Everything above it (QSearch, passes, counting) is shared by every engine.
/// </summary>
public interface IGroverEngine : IDisposable
{
    /// <summary>Name as chosen on the command line.</summary>
    string Name { get; }

    IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests);
}
