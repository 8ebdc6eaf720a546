using System.Collections;

namespace QuantumRayTracing.Rays;

/// <summary>
/// A read-only list whose item i is computed on each access, not stored: a pass's rays (camera rays, shadow rays) are
/// pure functions of their pixel or surface point, so a render keeps the few bytes that index them instead of an object
/// per ray (docs/rendering.md, large renders). The function must give the same item for the same index every time.
/// </summary>
public sealed class ComputedList<T>(int count, Func<int, T> item) : IReadOnlyList<T>
{
    public int Count { get; } = count >= 0 ? count : throw new ArgumentOutOfRangeException(nameof(count));

    public T this[int index] => (uint)index < (uint)Count ? item(index) : throw new ArgumentOutOfRangeException(nameof(index));

    public IEnumerator<T> GetEnumerator()
    {
        for (var i = 0; i < Count; i++) yield return item(i);
    }

    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
}
