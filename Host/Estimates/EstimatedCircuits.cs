using System.Globalization;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// Every circuit `qrt estimate` reports, in table order. A new circuit is one more entry here.
/// </summary>
public static class EstimatedCircuits
{
    /// <summary>Int_r (paper fig. 3) applied once, XORing i_r(p) into a fresh output qubit: the paper's table 9 circuit.</summary>
    public static readonly EstimatedCircuit Oracle = new(
        "oracle",
        "the intersection oracle Int_r once (compute the flags, XOR their AND into the output, uncompute)",
        s => $"{QSharpOperations.ApplyIntersectionOracleOnNewRegisters}({GateEngine.OracleArgument(s.Oracle)})",
        s => OracleRegisters.ForOracle(s.Oracle));

    /// <summary>One Grover iteration: the phase oracle and the reflection about the uniform superposition over N.</summary>
    public static readonly EstimatedCircuit GroverIteration = new(
        "Grover iteration",
        "one Grover iteration: the phase oracle, then the reflection about the uniform superposition over N",
        s => $"{QSharpOperations.ApplyGateGroverIterationOnNewRegisters}({GateEngine.OracleArgument(s.Oracle)})",
        s => OracleRegisters.For(s.Oracle));

    /// <summary>One QSearch run: prepare the uniform superposition, r iterations, measure the index.</summary>
    public static readonly EstimatedCircuit SearchRun = new(
        "QSearch run",
        "one run of QSearch: prepare the uniform superposition over N, r Grover iterations, measure the index",
        s => $"{QSharpOperations.MeasureGateGroverSearch}({GateEngine.OracleArgument(s.Oracle)}, {s.Iterations.ToString(CultureInfo.InvariantCulture)})",
        s => OracleRegisters.For(s.Oracle),
        RepeatsIterations: true);

    /// <summary>The QSS circuit: subpixel register in superposition, counter-controlled Grover powers, inverse QFT, measurement.</summary>
    public static readonly EstimatedCircuit QssReadout = new(
        "QSS readout",
        "quantum supersampling: the subpixels in superposition, 2^i coin Grover operators controlled by counter bit i, inverse QFT, measure the counter",
        s => $"{QSharpOperations.MeasureQssReadout}({s.CoinValues}, {s.CounterBits.ToString(CultureInfo.InvariantCulture)})",
        _ => null);

    /// <summary>One QCoin step: the shifted coin Q_F,E, one Grover operator G_F,E, one flip.</summary>
    public static readonly EstimatedCircuit QCoinStep = new(
        "QCoin step",
        "one QCoin step (i = 1): prepare the shifted coin Q_F,E, apply its Grover operator G_F,E once, flip (measure the coin)",
        s => $"{QSharpOperations.CountCoinHeads}(true, {s.CoinValues}, 1, 1)",
        _ => null);

    /// <summary>
    /// One query of a pooled search over the pool's (ray, primitive) pairs, XORing the pair's test into a fresh output
    /// qubit: its ray's window by a lookup over the rays, its row by a lookup over the pairs, the one-ray oracle's comparators.
    /// </summary>
    public static readonly EstimatedCircuit PooledQuery = new(
        "pooled query",
        "one query of a pooled search: the ray's window looked up over the pool's rays, the pair's row over its rays x N pairs, the comparators, XOR into the output, uncompute",
        s => $"{QSharpOperations.ApplyPooledQueryOnNewRegisters}({GateEngine.PooledArgument(PoolOf(s))})",
        _ => null);

    /// <summary>One Grover iteration of a pooled search: the pooled query in phase form and the reflection about the uniform superposition over the pairs.</summary>
    public static readonly EstimatedCircuit PooledIteration = new(
        "pooled iteration",
        "one Grover iteration of a pooled search: the pooled query in phase form, then the reflection about the uniform superposition over the pairs",
        s => $"{QSharpOperations.ApplyPooledGroverIterationOnNewRegisters}({GateEngine.PooledArgument(PoolOf(s))})",
        _ => null);

    /// <summary>The circuits of one pooled search, for `estimate --pooled`.</summary>
    public static IReadOnlyList<EstimatedCircuit> Pooled { get; } = [PooledQuery, PooledIteration];

    private static IReadOnlyList<OracleInput> PoolOf(EstimateSubject subject) =>
        subject.Pool ?? throw new ArgumentException("a pooled circuit needs the subject's pool of rays", nameof(subject));

    /// <summary>The circuits of one ray, for the oracle's tables and checks.</summary>
    public static IReadOnlyList<EstimatedCircuit> Ray { get; } = [Oracle, GroverIteration, SearchRun];

    public static IReadOnlyList<EstimatedCircuit> All { get; } = [.. Ray, QssReadout, QCoinStep];
}
