using System.Globalization;
using System.Text;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>
/// Runs ray searches with the gate-level intersection oracle of paper sec. 4.2 (coordinate lookups,
/// comparators, flags, everything uncomputed) on the QDK full-state simulator: exact and slow, for
/// validation on single rays or small images and for resource estimates. Every request must carry
/// its <see cref="GroverRequest.Oracle"/>; the marked set is then what the circuit computes, not an
/// input. Batches are cut and spread over the workers as in <see cref="FullStateEngine"/>, with each
/// call also held to a simulation budget (<see cref="MaxCostPerCall"/>). Under a <see cref="NoiseModel"/>
/// the calls run on the noisy simulator; qubit loss is refused (see <see cref="Noise"/>).
/// </summary>
public sealed class GateEngine(BridgePool pool, int maxRequestsPerCall = GateEngine.DefaultMaxRequestsPerCall, int maxQubits = GateEngine.DefaultMaxQubits, bool ownsPool = true, NoiseModel? noise = null) : IGroverEngine
{
    /// <summary>
    /// The noise every call runs under. Pauli noise only: the oracle uncomputes with mid-circuit
    /// measurements (the library's <c>Adjoint AND</c> and unlookup) whose results a lost qubit leaves undefined.
    /// </summary>
    public NoiseModel Noise { get; } = noise is { QubitLoss: > 0 }
        ? throw new ArgumentException(LossUnsupported, nameof(noise))
        : noise ?? NoiseModel.None;

    /// <summary>Why the gate engine refuses qubit loss, as the command line reports it.</summary>
    public const string LossUnsupported = "the gate engine cannot simulate qubit loss: its oracle uncomputes with mid-circuit measurements, which a lost qubit leaves without a result";

    /// <summary>
    /// Default of <see cref="MaxQubits"/>. The QDK's simulator is sparse: it stores only the nonzero
    /// amplitudes (at most N here, as every work register is a function of the index), so width alone
    /// costs little. The limit keeps the engine to the searches it is for: the widest of the shipped
    /// scenes (qornell-512, 72 qubits with the compact oracle) with room for secondary rays' extra
    /// depth bits; wider requests come from scenes the engine would simulate for hours.
    /// </summary>
    public const int DefaultMaxQubits = 80;

    /// <summary>Peak qubits (<see cref="OracleRegisters.PeakQubits"/>) a request may need; a wider one fails the whole batch before any simulation.</summary>
    public int MaxQubits => maxQubits;

    /// <summary>At N = 8 a run costs a few milliseconds, so a hundred of them outweigh the ~60 ms compile of a call.</summary>
    public const int DefaultMaxRequestsPerCall = 100;

    /// <summary>
    /// Budget of one call in units of <see cref="Cost"/>. The simulated state holds N amplitudes and
    /// each lookup touches every row, so an iteration costs about N² · 1.7 µs at large N (measured: 0.9 s
    /// at N = 512); 3·10⁶ units keep a call near 5 s, far below the bridge's time limit, while a single
    /// run of any size still gets a call of its own.
    /// </summary>
    public const double MaxCostPerCall = 3e6;

    /// <summary>A request's simulation cost: (r + 1) · N², the preparation counted as one iteration.</summary>
    public static double Cost(GroverRequest request) => (request.Iterations + 1.0) * request.Marked.Count * request.Marked.Count;

    public string Name => "gate";

    public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests)
    {
        (OracleInput Input, OracleRegisters Registers)? widest = null;
        for (var k = 0; k < requests.Count; k++)
        {
            var oracle = requests[k].Oracle
                ?? throw new ArgumentException($"request {k} has no oracle input: the gate engine searches rays, not bare marked sets", nameof(requests));
            if (oracle.Table.Count != requests[k].Marked.Count)
                throw new ArgumentException($"request {k} searches {requests[k].Marked.Count} indices but its ray table has {oracle.Table.Count} rows", nameof(requests));
            var registers = OracleRegisters.For(oracle);
            if (widest is not { } w || registers.PeakQubits > w.Registers.PeakQubits) widest = (oracle, registers);
        }
        // The whole batch is checked before any of it is sent, so a refused render allocates nothing.
        if (widest is { } wide && wide.Registers.PeakQubits > maxQubits)
            throw new QubitLimitException(wide.Input, wide.Registers, maxQubits);
        return BridgeBatches.Measure(pool, requests, new ChunkLimits(maxRequestsPerCall, Cost, MaxCostPerCall), QSharpOperations.MeasureGateGroverBatch, BatchExpression, Noise);
    }

    /// <summary>The Q# call for a batch: <c>MeasureGateGroverBatch([(input, r), …])</c>.</summary>
    public static string BatchExpression(IReadOnlyList<GroverRequest> requests)
    {
        var text = new StringBuilder(QSharpOperations.MeasureGateGroverBatch).Append("([");
        for (var k = 0; k < requests.Count; k++)
        {
            if (k > 0) text.Append(", ");
            var oracle = requests[k].Oracle ?? throw new ArgumentException($"request {k} has no oracle input", nameof(requests));
            text.Append('(').Append(OracleArgument(oracle)).Append(", ")
                .Append(requests[k].Iterations.ToString(CultureInfo.InvariantCulture)).Append(')');
        }
        return text.Append("])").ToString();
    }

    /// <summary>
    /// The Q# value of one search's oracle input, an <c>IntersectionInput</c>: widths, bounds
    /// [minX, maxX, minY, maxY, minZ, maxZ] and point [x, y, z] per row, validity, depths, the
    /// clamped comparator constants (<see cref="OracleConstants"/>), each primitive's flat axis and the
    /// construction.
    /// </summary>
    public static string OracleArgument(OracleInput input)
    {
        ArgumentNullException.ThrowIfNull(input);
        var table = input.Table;
        var geometry = input.Geometry;
        var constants = OracleConstants.For(input);
        var n = table.Count;
        var text = new StringBuilder("new ").Append(QSharpTypes.IntersectionInput).Append(" { CoordinateBits = ").Append(Int(table.CoordinateBits))
            .Append(", DepthBits = ").Append(Int(table.DepthBits)).Append(", Bounds = [");
        for (var p = 0; p < n; p++)
        {
            text.Append(p > 0 ? ", [" : "[");
            for (var axis = 0; axis < 3; axis++)
                text.Append(axis > 0 ? ", " : "").Append(Int(geometry.Min(p, axis))).Append(", ").Append(Int(geometry.Max(p, axis)));
            text.Append(']');
        }
        text.Append("], Points = [");
        for (var p = 0; p < n; p++)
            text.Append(p > 0 ? ", [" : "[").Append(Int(table.Point(p, 0))).Append(", ").Append(Int(table.Point(p, 1)))
                .Append(", ").Append(Int(table.Point(p, 2))).Append(']');
        text.Append("], Valid = [");
        for (var p = 0; p < n; p++)
            text.Append(p > 0 ? ", " : "").Append(table.IsValid(p) ? "true" : "false");
        text.Append("], Depths = [");
        for (var p = 0; p < n; p++)
            text.Append(p > 0 ? ", " : "").Append(Int(table.Depth(p)));
        text.Append("], Near = ").Append(constants.Near.ToString(CultureInfo.InvariantCulture))
            .Append(", Limit = ").Append(constants.Limit.ToString(CultureInfo.InvariantCulture)).Append(", FlatAxes = [");
        for (var p = 0; p < n; p++)
            text.Append(p > 0 ? ", " : "").Append(Int(geometry.FlatAxis(p)));
        var construction = input.Construction;
        return text.Append("], Construction = new ").Append(QSharpTypes.OracleConstruction)
            .Append(" { InPlaneAxes = ").Append(Bool(construction.InPlaneAxes))
            .Append(", BothBounds = ").Append(Bool(construction.BothBounds))
            .Append(", MeasuredUnload = ").Append(Bool(construction.MeasuredUnload))
            .Append(", ConstantBounds = ").Append(Bool(construction.ConstantBounds)).Append(" } }").ToString();
    }

    /// <summary>
    /// The Q# value of a pool's searches for one pooled query, an <c>IntersectionInput[]</c>: each ray's
    /// <see cref="OracleArgument"/>, in pool order (the pair register's ray part indexes them).
    /// </summary>
    public static string PooledArgument(IReadOnlyList<OracleInput> pool)
    {
        ArgumentNullException.ThrowIfNull(pool);
        if (pool.Count == 0) throw new ArgumentException("a pool needs at least one ray", nameof(pool));
        return "[" + string.Join(", ", pool.Select(OracleArgument)) + "]";
    }

    private static string Bool(bool value) => value ? "true" : "false";

    private static string Int(int value) => value.ToString(CultureInfo.InvariantCulture);

    public BridgePool Pool => pool;

    /// <summary>Stops the engine's bridges, unless the pool is shared (<c>ownsPool</c> false).</summary>
    public void Dispose()
    {
        if (ownsPool) pool.Dispose();
    }
}
