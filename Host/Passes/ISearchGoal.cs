using QuantumRayTracing.Intersection;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// What a search pass (<see cref="SearchPass"/>) looks for and keeps per ray: the closest hit (<see cref="TracePass"/>) or any
/// occluder (<see cref="DirectPass"/>). The pass's skeleton (rounds, lattice order, stop rule, classical settling, ledger and
/// budget rounds) is the same for both; only these differ.
/// </summary>
public interface ISearchGoal
{
    /// <summary>Whether a find settles the ray (an occluder ends a shadow ray) rather than start a search for a closer one.</summary>
    bool FindEnds { get; }

    /// <summary>The primitives ray <paramref name="ray"/>'s next search accepts: beyond its best hit, or the full range.</summary>
    HitWindow Window(int ray, RayTable table);

    /// <summary>Takes a search's outcome into the ray's answer.</summary>
    void Apply(int ray, RayTable table, HitOutcome outcome);

    /// <summary>Rays finished by a find (an occluder, also one a neighbour lent); null when a find never finishes a ray. Only reads.</summary>
    Func<int, bool>? Found { get; }

    /// <summary>NeighOpt after a round: each ray tests its neighbours' answers.</summary>
    (long Tests, long Updated) Gather(PixelLayout layout);

    /// <summary>Before a lattice level is searched, its rays test their lattice neighbours' answers.</summary>
    (long Tests, long Updated) FromLattice(int[] levelRays, PixelLayout layout, int levels, bool[] agreed);
}
