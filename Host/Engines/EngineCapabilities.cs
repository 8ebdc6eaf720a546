namespace QuantumRayTracing.Engines;

/// <summary>
/// What each engine can do: the one place that knows which kind runs Q#, searches with Grover runs or models
/// which noise, so callers ask the engine instead of listing kinds.
/// </summary>
public static class EngineCapabilities
{
    extension(EngineKind kind)
    {
        /// <summary>The name --engine and every report use.</summary>
        public string Name => kind.ToString().ToLowerInvariant();

        /// <summary>Runs Q# on the QDK simulator through Node bridges (local or a cluster's); its outcomes cannot be seeded.</summary>
        public bool RunsQSharp => kind is EngineKind.FullState or EngineKind.Gate;

        /// <summary>Searches with Grover runs (QSearch), so it runs under a noise model and may miss hits.</summary>
        public bool SearchesWithGrover => kind is EngineKind.FullState or EngineKind.Gate or EngineKind.Analytic;

        /// <summary>Simulates the gate-level intersection oracle: exact, slow, tiny images only.</summary>
        public bool SimulatesOracleGates => kind == EngineKind.Gate;

        /// <summary>
        /// Searches scenes of any primitive kind: every engine whose tables are computed classically. The gate-level
        /// oracle's circuits compare a point with a rectangle's bounds, so the gate engine takes rectangles only.
        /// </summary>
        public bool TakesAnyPrimitive => !kind.SimulatesOracleGates;

        /// <summary>Runs the QDK's qubit-loss model.</summary>
        public bool ModelsQubitLoss => kind == EngineKind.FullState;

        /// <summary>
        /// Runs a device noise model (gate rates by arity, readout error): the analytic engine through its approximation, the
        /// fullstate engine with each gate's rate set inside Q#. The gate engine's oracle is built from the QDK's arithmetic,
        /// whose gates take one Pauli rate.
        /// </summary>
        public bool RunsDeviceNoise => kind is EngineKind.Analytic or EngineKind.FullState;

        /// <summary>Runs Pauli noise through its depolarizing approximation rather than the noisy simulator.</summary>
        public bool ApproximatesNoise => kind == EngineKind.Analytic;

        /// <summary>Certain answers, every ray's best hit: brute force (the reference every render is compared with) and the BVH.</summary>
        public bool IsExact => kind is EngineKind.Classical or EngineKind.Bvh;

        /// <summary>The same seed gives the same bytes: every engine whose randomness is ours.</summary>
        public bool IsSeedable => !kind.RunsQSharp;

        /// <summary>Its searches draw from the seed, so another seed gives another render.</summary>
        public bool DrawsFromSeed => kind.IsSeedable && !kind.IsExact;
    }
}
