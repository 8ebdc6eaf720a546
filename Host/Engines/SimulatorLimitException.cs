namespace QuantumRayTracing.Engines;

/// <summary>
/// A request the simulator would not hold within the engine's limits, refused before any of its
/// batch was simulated: one line naming the request, what it needs and the limit.
/// </summary>
public class SimulatorLimitException(string message) : Exception(message);
