namespace QuantumRayTracing.Estimates;

/// <summary>
/// A group of runs (a pass or the frame) on one qubit model under one budget: the physical qubits of
/// the widest run (what one quantum processor must hold), the runtime one after another and on
/// <see cref="FrameCost.Qpus"/> processors, the smallest and largest code distance the estimator chose,
/// and the sum of the runs' failure bounds (<see cref="RunErrors.FailureBound"/>), a union bound on
/// the probability that any of them fails.
/// </summary>
/// <param name="PhysicalQubits">Per processor: the widest run's physical qubits (algorithm and T factories).</param>
/// <param name="SequentialNanoseconds">Σ of the runs' runtimes.</param>
/// <param name="ParallelNanoseconds">Engine batches one after another, each batch's runs spread over the processors (<see cref="FrameCost.Makespan"/>).</param>
/// <param name="MinCodeDistance">The smallest code distance of a run.</param>
/// <param name="MaxCodeDistance">The largest: what a machine running every run at one distance needs.</param>
/// <param name="FailureBound">Σ of the runs' failure bounds.</param>
public sealed record FramePhysical(long PhysicalQubits, double SequentialNanoseconds, double ParallelNanoseconds, int MinCodeDistance, int MaxCodeDistance, double FailureBound);
