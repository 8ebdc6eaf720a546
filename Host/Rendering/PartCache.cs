namespace QuantumRayTracing.Rendering;

/// <summary>
/// A worker's last scene and engine, ready to render parts: a frame's parts all carry the same, so the scene is read and its
/// noise model counted once per frame, not once per part.
/// </summary>
public sealed class PartCache
{
    private readonly Lock _gate = new();
    private (string Key, LocalParts Parts)? _last;

    public LocalParts For(string key, Func<LocalParts> build)
    {
        lock (_gate)
        {
            if (_last is { } last && last.Key == key) return last.Parts;
            var parts = build();
            _last = (key, parts);
            return parts;
        }
    }
}
