using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Experiments;

/// <summary>What a soak found for one scene on one engine.</summary>
public enum SoakStatus
{
    Ok,
    Failed,
    Skipped,
}

/// <summary>
/// One row of a soak: a scene on an engine over every seed. <see cref="Scene"/> is the file's stem;
/// <see cref="Engine"/> is null for a scene that did not load. Measures are over the first render of
/// each seed: <see cref="WallTime"/> per render on average, <see cref="IntPerRay"/> the mean Int/Ray
/// (conservative), <see cref="Nrmse"/> and <see cref="DifferentPixels"/> the worst seed's error against
/// the classical render of the same options, <see cref="PixelBound"/> the #Dpix allowed (null: not
/// checked). <see cref="Deterministic"/>: true/false when the same seed was rendered twice, null where the
/// engine cannot be seeded. <see cref="SeedEffect"/> says what a second seed changed. <see cref="Reason"/>
/// explains a failure or a skip.
/// </summary>
public sealed record SoakRow(
    string Scene,
    int Primitives,
    EngineKind? Engine,
    SoakStatus Status,
    string Reason,
    int Size = 0,
    int Renders = 0,
    TimeSpan WallTime = default,
    double? IntPerRay = null,
    double? Nrmse = null,
    int? DifferentPixels = null,
    int? PixelBound = null,
    bool? Deterministic = null,
    string SeedEffect = "")
{
    public static SoakRow Skipped(string scene, int primitives, EngineKind engine, string reason) =>
        new(scene, primitives, engine, SoakStatus.Skipped, reason);

    /// <summary>"ok", "FAILED: reason" or "skipped: reason".</summary>
    public string StatusText => Status switch
    {
        SoakStatus.Ok => "ok",
        SoakStatus.Failed => "FAILED: " + Reason,
        _ => "skipped: " + Reason,
    };
}
