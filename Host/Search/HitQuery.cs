using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Search;

/// <summary>
/// One ray search: find a primitive whose row of <see cref="Table"/> verify-rpc accepts under
/// <see cref="Window"/>. <see cref="Schedule"/>, when set, replaces QSearch's usual schedule (a
/// confirmation list); the classical engines ignore it.
/// </summary>
public readonly record struct HitQuery(RayTable Table, HitWindow Window, QSearchSchedule? Schedule = null);
