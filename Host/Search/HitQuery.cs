using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Search;

/// <summary>One ray search: find a primitive whose row of <see cref="Table"/> verify-rpc accepts under <see cref="Window"/>.</summary>
public readonly record struct HitQuery(RayTable Table, HitWindow Window);
