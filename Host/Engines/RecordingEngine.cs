using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>
/// The engine seam with a listener: every batch goes to the inner engine unchanged, and the listener
/// sees its requests first. Lets a caller count what a render asks of the quantum machine without
/// touching the passes above the seam or the engine below it.
/// </summary>
public sealed class RecordingEngine(IGroverEngine inner, Action<IReadOnlyList<GroverRequest>> listener) : IGroverEngine
{
    public string Name => inner.Name;

    public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests)
    {
        listener(requests);
        return inner.Measure(requests);
    }

    public void Dispose() => inner.Dispose();
}
