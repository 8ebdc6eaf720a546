namespace QuantumRayTracing.Output;

/// <summary>
/// Where a run's Q# work ran, as its reports name it. <see cref="Description"/> is the text printed after "ran on";
/// the other members say the same for scripts: <see cref="Kind"/> "local" (this machine) or "cluster", the
/// bridges that served the requests (0 when the engine runs no Q#), and on a cluster its id, its membership, its
/// worker processes and the chunks sent again after a worker failed to answer.
/// </summary>
public sealed record RunPlace(
    string Description,
    string Kind,
    int Bridges,
    string? Cluster = null,
    string? Membership = null,
    int? Workers = null,
    int? ChunksSentAgain = null)
{
    public const string LocalKind = "local";

    public const string ClusterKind = "cluster";

    /// <summary>An engine that runs no Q# (analytic, classical, randomized): everything on this machine.</summary>
    public static readonly RunPlace NoBridges = new("this machine (no Q# bridges)", LocalKind, 0);

    /// <summary><paramref name="bridges"/> Node bridges started on this machine.</summary>
    public static RunPlace LocalBridges(int bridges) =>
        new($"this machine, {bridges} local bridge{(bridges == 1 ? "" : "s")}", LocalKind, bridges);
}
