using System.Globalization;
using System.Text;
using System.Text.Json;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Estimation;

/// <summary>
/// Runs the supersampling circuits as Q# on the QDK full-state simulator: a batch is cut into chunks of
/// bounded simulation work, each chunk is one call of <c>CountCoinHeadsBatch</c>, <c>CountDirectCoinHeadsBatch</c> or <c>MeasureQssBatch</c>
/// on its own bridge, and the chunks run on all workers at once. Outcomes cannot be seeded. A batch
/// holding a circuit wider than <see cref="MaxQubits"/> is refused before any of it is sent. Under a
/// <see cref="NoiseModel"/> other than the ideal one the calls run on the noisy simulator. Under a <see cref="DeviceNoiseModel"/>
/// the single-qubit coins and QSS on them run as <c>CountDirectCoinHeadsOnDeviceBatch</c> and <c>MeasureDirectQssOnDeviceBatch</c>,
/// which set each gate's rate inside Q#, and the host flips the measured bits by the readout error with
/// <paramref name="readoutRandom"/>, in request order.
/// </summary>
public sealed class FullStateCoinEngine(BridgePool pool, bool ownsPool = true, int? maxQubits = null, NoiseModel? noise = null,
    DeviceNoiseModel? device = null, SeededRandom? readoutRandom = null) : ICoinEngine
{
    /// <summary>The noise every call runs under.</summary>
    public NoiseModel Noise { get; } = noise ?? NoiseModel.None;

    /// <summary>The device model the single-qubit coins run under, or null; it replaces <see cref="Noise"/>, which must then be ideal.</summary>
    public DeviceNoiseModel? Device { get; } = DeviceNoiseModel.Alone(device, noise);

    private readonly ReadoutFlips? _readout = ReadoutFlips.For(device, readoutRandom);

    /// <summary>Oracle applications (each N controlled rotations) per call: a few seconds of simulation, far below the bridge's time limit.</summary>
    public const double MaxOracleCallsPerChunk = 20_000;

    public string Name => "fullstate";

    /// <summary>Qubits a circuit may use: by default the widest dense state this machine holds (<see cref="SimulatorCapacity"/>).</summary>
    public int MaxQubits { get; } = maxQubits ?? SimulatorCapacity.DefaultMaxQubits(pool.Workers);

    private static int CoinQubits(CoinRequest request) => CoinRegisters.Coin(request.Kind, request.Amplitudes.Length);

    private static int QssQubits(QssRequest request) => CoinRegisters.Qss(request.Amplitudes.Length, request.CounterBits);

    public IReadOnlyList<int> FlipCoins(IReadOnlyList<CoinRequest> requests)
    {
        if (requests.Count > 0)
        {
            var widest = requests.MaxBy(CoinQubits)!;
            var qubits = CoinQubits(widest);
            SimulatorCapacity.Check($"a coin over {widest.Amplitudes.Length} subpixels", qubits, qubits, MaxQubits);
        }
        // The direct coin is its own Q# operation; each kind's requests go as one batch, answers back in request order.
        var heads = new int[requests.Count];
        var direct = Enumerable.Range(0, requests.Count).Where(k => requests[k].Kind == CoinKind.Direct).ToArray();
        var subpixel = Enumerable.Range(0, requests.Count).Where(k => requests[k].Kind != CoinKind.Direct).ToArray();
        if (Device is not null && subpixel.Length > 0) throw new ArgumentException(AnalyticCoinEngine.DeviceNeedsDirectCoins);
        FlipBatch(subpixel.Select(k => requests[k]).ToArray(), r => (double)r.Queries * r.Amplitudes.Length, QSharpOperations.CountCoinHeadsBatch, CoinExpression, subpixel, heads);
        if (Device is { } model)
            FlipBatch(direct.Select(k => requests[k]).ToArray(), r => r.Queries, QSharpOperations.CountDirectCoinHeadsOnDeviceBatch, c => DeviceCoinExpression(model, c), direct, heads);
        else
            FlipBatch(direct.Select(k => requests[k]).ToArray(), r => r.Queries, QSharpOperations.CountDirectCoinHeadsBatch, DirectCoinExpression, direct, heads);
        if (_readout is not null)
            for (var k = 0; k < heads.Length; k++) heads[k] = _readout.ReadHeads(heads[k], requests[k].Flips);
        return heads;
    }

    private void FlipBatch(CoinRequest[] requests, Func<CoinRequest, double> cost, string operation, Func<IReadOnlyList<CoinRequest>, string> expression, int[] positions, int[] heads) =>
        Run(requests, cost, operation, expression, (chunk, start, json) =>
        {
            var values = JsonSerializer.Deserialize<int[]>(json) ?? throw new BridgeException($"{operation} returned no value");
            if (values.Length != chunk.Count) throw new BridgeException($"{operation} returned {values.Length} counts for {chunk.Count} requests");
            for (var k = 0; k < chunk.Count; k++)
            {
                if (values[k] < 0 || values[k] > chunk[k].Flips) throw new BridgeException($"{operation} returned {values[k]} heads of {chunk[k].Flips} flips");
                heads[positions[start + k]] = values[k];
            }
        });

    public IReadOnlyList<int[]> ReadCounters(IReadOnlyList<QssRequest> requests)
    {
        if (requests.Count > 0)
        {
            var widest = requests.MaxBy(QssQubits)!;
            var qubits = QssQubits(widest);
            SimulatorCapacity.Check($"a QSS readout with {widest.CounterBits} counter bits over {widest.Amplitudes.Length} subpixels", qubits, qubits, MaxQubits);
        }
        var readouts = new int[requests.Count][];
        var direct = Enumerable.Range(0, requests.Count).Where(k => requests[k].Coin == CoinKind.Direct).ToArray();
        var subpixel = Enumerable.Range(0, requests.Count).Where(k => requests[k].Coin != CoinKind.Direct).ToArray();
        if (Device is not null && subpixel.Length > 0) throw new ArgumentException(AnalyticCoinEngine.DeviceNeedsDirectCoins);
        if (direct.Length > 0 && !Noise.IsNoiseless) throw new ArgumentException("QSS on the single-qubit coin runs noiseless or under a device model");
        var model = Device ?? new DeviceNoiseModel(0, 0);
        ReadBatch(subpixel.Select(k => requests[k]).ToArray(), r => r.Amplitudes.Length, QSharpOperations.MeasureQssBatch, QssExpression, subpixel, readouts);
        ReadBatch(direct.Select(k => requests[k]).ToArray(), _ => 1, QSharpOperations.MeasureDirectQssOnDeviceBatch, c => DeviceQssExpression(model, c), direct, readouts);
        if (_readout is not null)
            for (var k = 0; k < readouts.Length; k++)
                for (var shot = 0; shot < readouts[k].Length; shot++) readouts[k][shot] = _readout.ReadBits(readouts[k][shot], requests[k].CounterBits);
        return readouts;
    }

    private void ReadBatch(QssRequest[] requests, Func<QssRequest, double> width, string operation, Func<IReadOnlyList<QssRequest>, string> expression, int[] positions, int[][] readouts) =>
        Run(requests, r => r.Shots * QssRequest.QueriesPerRun(r.CounterBits) * width(r), operation, expression, (chunk, start, json) =>
        {
            var values = JsonSerializer.Deserialize<int[][]>(json) ?? throw new BridgeException($"{operation} returned no value");
            if (values.Length != chunk.Count) throw new BridgeException($"{operation} returned {values.Length} results for {chunk.Count} requests");
            for (var k = 0; k < chunk.Count; k++)
            {
                if (values[k].Length != chunk[k].Shots || values[k].Any(y => y < 0 || y >= 1 << chunk[k].CounterBits))
                    throw new BridgeException($"{operation} returned readouts outside 0..{(1 << chunk[k].CounterBits) - 1} or the wrong number of them");
                readouts[positions[start + k]] = values[k];
            }
        });

    private void Run<T>(IReadOnlyList<T> requests, Func<T, double> cost, string operation, Func<IReadOnlyList<T>, string> expression,
        Action<IReadOnlyList<T>, int, string> accept)
    {
        if (requests.Count == 0) return;
        pool.ForEach(Chunks(requests, cost, pool.Workers), (chunk, bridge) =>
        {
            var slice = requests.Skip(chunk.Start).Take(chunk.Length).ToArray();
            accept(slice, chunk.Start, bridge.Run(expression(slice), noise: Device is null ? Noise : NoiseModel.None)[0]);
        });
    }

    /// <summary>Consecutive chunks of at most <see cref="MaxOracleCallsPerChunk"/> work (one request may exceed it alone), at least one per worker.</summary>
    internal static List<(int Start, int Length)> Chunks<T>(IReadOnlyList<T> requests, Func<T, double> cost, int workers)
    {
        var total = requests.Sum(cost);
        var budget = Math.Min(MaxOracleCallsPerChunk, Math.Max(1, total / workers));
        var chunks = new List<(int Start, int Length)>();
        var (start, sum) = (0, 0.0);
        for (var k = 0; k < requests.Count; k++)
        {
            var next = cost(requests[k]);
            if (k > start && sum + next > budget)
            {
                chunks.Add((start, k - start));
                (start, sum) = (k, 0.0);
            }
            sum += next;
        }
        chunks.Add((start, requests.Count - start));
        return chunks;
    }

    /// <summary>The single-ancilla shots, one batch; the ancilla is one qubit more than the coin.</summary>
    public IReadOnlyList<int> CountAncillaZeros(IReadOnlyList<AncillaPhaseRequest> requests)
    {
        if (requests.Count == 0) return [];
        if (Device is not null) throw new ArgumentException(AnalyticCoinEngine.DeviceNeedsDirectCoins);
        var widest = requests.MaxBy(r => r.Amplitudes.Length)!;
        var qubits = CoinRegisters.Coin(CoinKind.Mean, widest.Amplitudes.Length) + 1;
        SimulatorCapacity.Check($"a single-ancilla shot over {widest.Amplitudes.Length} subpixels", qubits, qubits, MaxQubits);
        var zeros = new int[requests.Count];
        const string operation = QSharpOperations.CountAncillaZerosBatch;
        Run(requests, r => (double)r.Queries * r.Amplitudes.Length, operation, AncillaExpression, (chunk, start, json) =>
        {
            var values = JsonSerializer.Deserialize<int[]>(json) ?? throw new BridgeException($"{operation} returned no value");
            if (values.Length != chunk.Count) throw new BridgeException($"{operation} returned {values.Length} counts for {chunk.Count} requests");
            for (var k = 0; k < chunk.Count; k++)
            {
                if (values[k] < 0 || values[k] > chunk[k].Shots) throw new BridgeException($"{operation} returned {values[k]} zeros of {chunk[k].Shots} shots");
                zeros[start + k] = values[k];
            }
        });
        return zeros;
    }

    public static string AncillaExpression(IReadOnlyList<AncillaPhaseRequest> requests) =>
        AmplitudesCountsExpression(QSharpOperations.CountAncillaZerosBatch, requests.Select(r => (r.Amplitudes, r.Power, r.Shots)));

    public static string CoinExpression(IReadOnlyList<CoinRequest> requests)
    {
        var text = new StringBuilder(QSharpOperations.CountCoinHeadsBatch).Append("([");
        for (var k = 0; k < requests.Count; k++)
        {
            var r = requests[k];
            if (k > 0) text.Append(", ");
            text.Append('(').Append(r.Kind == CoinKind.Shifted ? "true" : "false").Append(", ");
            AppendDoubles(text, r.Amplitudes);
            text.Append(", ").Append(r.Iterations.ToString(CultureInfo.InvariantCulture))
                .Append(", ").Append(r.Flips.ToString(CultureInfo.InvariantCulture)).Append(')');
        }
        return text.Append("])").ToString();
    }

    /// <summary>The direct coins' call: each request's head amplitude √f (<see cref="CoinProbability.HeadAmplitude"/>), m and flips.</summary>
    public static string DirectCoinExpression(IReadOnlyList<CoinRequest> requests)
    {
        var text = new StringBuilder(QSharpOperations.CountDirectCoinHeadsBatch).Append("([");
        for (var k = 0; k < requests.Count; k++)
        {
            var r = requests[k];
            if (k > 0) text.Append(", ");
            text.Append('(').Append(QSharpDouble(CoinProbability.HeadAmplitude(CoinKind.Direct, r.Amplitudes)))
                .Append(", ").Append(r.Iterations.ToString(CultureInfo.InvariantCulture))
                .Append(", ").Append(r.Flips.ToString(CultureInfo.InvariantCulture)).Append(')');
        }
        return text.Append("])").ToString();
    }

    /// <summary>The single-qubit coins' call under a device model: the one-qubit rate, then each request's √f, m and flips.</summary>
    public static string DeviceCoinExpression(DeviceNoiseModel device, IReadOnlyList<CoinRequest> requests) =>
        $"{QSharpOperations.CountDirectCoinHeadsOnDeviceBatch}({QSharpDouble(device.OneQubit)}, {DirectCoinExpression(requests)[(QSharpOperations.CountDirectCoinHeadsBatch.Length + 1)..]}";

    /// <summary>QSS on the single-qubit coin: the one- and two-qubit rates, then each request's √f, t and shots.</summary>
    public static string DeviceQssExpression(DeviceNoiseModel device, IReadOnlyList<QssRequest> requests)
    {
        var text = new StringBuilder(QSharpOperations.MeasureDirectQssOnDeviceBatch).Append('(')
            .Append(QSharpDouble(device.OneQubit)).Append(", ").Append(QSharpDouble(device.TwoQubit)).Append(", [");
        for (var k = 0; k < requests.Count; k++)
        {
            var r = requests[k];
            if (k > 0) text.Append(", ");
            text.Append('(').Append(QSharpDouble(r.Amplitudes[0])).Append(", ").Append(r.CounterBits.ToString(CultureInfo.InvariantCulture))
                .Append(", ").Append(r.Shots.ToString(CultureInfo.InvariantCulture)).Append(')');
        }
        return text.Append("])").ToString();
    }

    public static string QssExpression(IReadOnlyList<QssRequest> requests) =>
        AmplitudesCountsExpression(QSharpOperations.MeasureQssBatch, requests.Select(r => (r.Amplitudes, r.CounterBits, r.Shots)));

    /// <summary>A batch call whose requests are (amplitudes, an Int, an Int) tuples.</summary>
    private static string AmplitudesCountsExpression(string operation, IEnumerable<(double[] Amplitudes, int First, int Second)> requests)
    {
        var text = new StringBuilder(operation).Append("([");
        var separator = "";
        foreach (var (amplitudes, first, second) in requests)
        {
            text.Append(separator).Append('(');
            AppendDoubles(text, amplitudes);
            text.Append(", ").Append(first.ToString(CultureInfo.InvariantCulture))
                .Append(", ").Append(second.ToString(CultureInfo.InvariantCulture)).Append(')');
            separator = ", ";
        }
        return text.Append("])").ToString();
    }

    /// <summary>A Q# Double[] literal; fixed notation with a decimal point, which Q# requires of a Double.</summary>
    private static void AppendDoubles(StringBuilder text, double[] values)
    {
        text.Append('[');
        for (var i = 0; i < values.Length; i++)
        {
            if (i > 0) text.Append(", ");
            text.Append(QSharpDouble(values[i]));
        }
        text.Append(']');
    }

    private static string QSharpDouble(double value) => Math.Clamp(value, -1, 1).ToString("0.0###################", CultureInfo.InvariantCulture);

    public void Dispose()
    {
        if (ownsPool) pool.Dispose();
    }
}
