using QuantumRayTracing.Bridge;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench render-results` measures: tables 2 and 3 at <paramref name="Size"/>², the engines side by side at
/// <paramref name="EngineSize"/>², scenes by stem from <paramref name="Scene"/>, on <paramref name="Pool"/>'s
/// bridges when given (a cluster) or local ones.
/// </summary>
public sealed record RenderResultsSettings(Func<string, Scene> Scene, int Size, int EngineSize, ulong Seed, int Workers, BridgePool? Pool = null);
