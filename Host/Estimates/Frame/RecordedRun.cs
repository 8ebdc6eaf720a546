namespace QuantumRayTracing.Estimates;

/// <summary>
/// One Grover run a render asked of the quantum machine: the pass it belongs to, the engine batch
/// it was sent in (batches run one after another, the runs of a batch are independent), its
/// oracle's shape and its Grover iterations r.
/// </summary>
public readonly record struct RecordedRun(string Pass, int Batch, OracleShape Shape, int Iterations)
{
    /// <summary>What a run's price depends on: one Resource Estimator job per distinct key.</summary>
    public (OracleShape Shape, int Iterations) Key => (Shape, Iterations);
}
