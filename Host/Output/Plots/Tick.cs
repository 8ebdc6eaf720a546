namespace QuantumRayTracing.Output.Plots;

/// <summary>
/// A tick on an axis at <paramref name="At"/>, in axis units (the value itself on a linear axis, its base-10
/// logarithm on a log axis). Major ticks get a grid line and usually a label; minor ticks only a short mark.
/// </summary>
internal readonly record struct Tick(double At, string? Label, bool Major);
