using QuantumRayTracing.Intersection;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// How a pass iterates: at most <see cref="Iterations"/> rounds (#IT); <see cref="Neighbours"/>, when
/// set, the layout neighbour gathering uses after each round; <see cref="Stop"/>, when set, the sec. 6.2
/// termination criterion deciding after each empty search whether a ray is searched again;
/// <see cref="Lattice"/>, with a layout, traces the coarse lattice of pixels first (see <see cref="LatticePlan"/>);
/// <see cref="Schedule"/>, when set, replaces the engine's QSearch schedule for every search not given a cheaper one;
/// <see cref="Allowance"/>, when set, the wrong rays the pass may leave in expectation, kept by <see cref="BudgetRounds"/>;
/// <see cref="Settle"/>: rays whose remaining quantum work would cost more than N tests are settled classically (<see cref="ClassicalSettle"/>).
/// </summary>
public sealed record PassOptions(
    int Iterations,
    TieBreak TieBreak = TieBreak.Strict,
    PixelLayout? Neighbours = null,
    StopRule? Stop = null,
    LatticePlan? Lattice = null,
    QSearchSchedule? Schedule = null,
    double? Allowance = null,
    bool Settle = false);

/// <summary>
/// Lattice-first tracing over <see cref="Levels"/> levels: the rays whose pixel coordinates are both
/// multiples of 2^Levels are searched first; then, level by level down to every pixel, each ray tests
/// its next-coarser lattice neighbours' results classically and gets one confirming search, with the
/// cheap <see cref="Agreed"/> schedule where those neighbours all agree (and it accepts what they hold)
/// and the engine's full schedule where they disagree. Null <see cref="Agreed"/>: the full schedule everywhere.
/// <see cref="Sized"/>: a pass with an allowance sizes each level's cheap confirmation instead (<see cref="CheapConfirmation"/>).
/// </summary>
public sealed record LatticePlan(int Levels, QSearchSchedule? Agreed, bool Sized = false);
