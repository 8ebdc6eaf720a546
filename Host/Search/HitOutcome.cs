namespace QuantumRayTracing.Search;

/// <summary>
/// What a ray search returned: an accepted primitive or none, whether that answer is certain (the
/// search tested every primitive and returned the best in the (depth, id) order, or proved there is
/// none), and what it cost.
/// </summary>
public readonly record struct HitOutcome(int? Primitive, bool Certain, SearchCost Cost);
