namespace QuantumRayTracing.Output;

/// <summary>
/// One run of a command as its <c>--json</c> file records it: the command, every option's value, the seed and
/// engine (null where the command has none), the noise model, <see cref="Figures"/>, the result records the
/// command printed its figures from, and where the work ran (<see cref="RanOn"/>; null for a command that names no place).
/// </summary>
public sealed record RunRecord(
    string Command,
    IReadOnlyDictionary<string, object?> Options,
    ulong? Seed,
    string? Engine,
    RunNoise Noise,
    object Figures,
    RunPlace? RanOn = null);
