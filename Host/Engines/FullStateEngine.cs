using System.Globalization;
using System.Text;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>
/// Runs Grover requests as Q# on the QDK full-state simulator: a batch is cut into chunks, each
/// chunk is one call of the Q# operation <c>MeasureGroverBatch</c> on one bridge, and the chunks run
/// on all workers at once (<see cref="BridgeBatches"/>). Registers are sized per request (see
/// <see cref="SearchRegisters"/>). Measurement outcomes come from the simulator and cannot be seeded.
/// A batch holding a search wider than <see cref="MaxQubits"/> is refused before any of it is sent.
/// Under a <see cref="NoiseModel"/> other than the ideal one the calls run on the noisy simulator.
/// </summary>
public sealed class FullStateEngine(BridgePool pool, int maxRequestsPerCall = FullStateEngine.DefaultMaxRequestsPerCall, int? maxQubits = null, bool ownsPool = true, NoiseModel? noise = null) : IGroverEngine
{
    /// <summary>Large enough to amortise the ~60 ms compile of every QDK call, small enough to spread over workers.</summary>
    public const int DefaultMaxRequestsPerCall = 500;

    public const string BatchOperation = "QuantumRayTracing.Search.MeasureGroverBatch";

    public string Name => "fullstate";

    /// <summary>The noise every call runs under.</summary>
    public NoiseModel Noise { get; } = noise ?? NoiseModel.None;

    /// <summary>Qubits a search may use: by default the widest dense state this machine holds (<see cref="SimulatorCapacity"/>).</summary>
    public int MaxQubits { get; } = maxQubits ?? SimulatorCapacity.DefaultMaxQubits(pool.Workers);

    public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests)
    {
        if (requests.Count > 0)
        {
            // Auxiliaries are borrowed clean inside a gate and never superposed: the state spans the index register.
            var widest = requests.Max(r => r.Marked.Count);
            var registers = SearchRegisters.For(widest);
            SimulatorCapacity.Check($"a search over N = {widest} indices", registers.PeakQubits, registers.IndexQubits, MaxQubits);
        }
        return BridgeBatches.Measure(pool, requests, ChunkLimits.Count(maxRequestsPerCall), BatchOperation, BatchExpression, Noise);
    }

    /// <summary>The Q# call for a batch: <c>MeasureGroverBatch([(N, [marked…], r), …])</c>.</summary>
    public static string BatchExpression(IReadOnlyList<GroverRequest> requests)
    {
        var text = new StringBuilder(BatchOperation).Append("([");
        for (var k = 0; k < requests.Count; k++)
        {
            if (k > 0) text.Append(", ");
            var request = requests[k];
            text.Append('(').Append(request.Marked.Count.ToString(CultureInfo.InvariantCulture)).Append(", ");
            var indices = request.Marked.Indices;
            // An empty literal [] has no element type for Q# to infer from.
            text.Append(indices.IsEmpty ? "[0, size = 0" : "[");
            for (var i = 0; i < indices.Length; i++)
            {
                if (i > 0) text.Append(", ");
                text.Append(indices[i].ToString(CultureInfo.InvariantCulture));
            }
            text.Append("], ").Append(request.Iterations.ToString(CultureInfo.InvariantCulture)).Append(')');
        }
        return text.Append("])").ToString();
    }

    public BridgePool Pool => pool;

    /// <summary>Stops the engine's bridges, unless the pool is shared (<c>ownsPool</c> false).</summary>
    public void Dispose()
    {
        if (ownsPool) pool.Dispose();
    }
}
