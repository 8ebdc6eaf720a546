namespace QuantumRayTracing.Estimation;

/// <summary>
/// QSS for continuous values (paper 003 sec. 3.3): one run of the circuit with t counter bits per item,
/// estimate = sin²(πy/2^t) from the readout y. 2^(t+1) − 1 queries.
/// </summary>
public sealed class QssEstimator : IMeanEstimator
{
    public QssEstimator(int counterBits)
    {
        if (counterBits < 1 || counterBits > 16) throw new ArgumentOutOfRangeException(nameof(counterBits), counterBits, "QSS takes 1 to 16 counter bits");
        CounterBits = counterBits;
    }

    public int CounterBits { get; }

    public string Name => $"qss (t = {CounterBits})";

    public long Queries => QssRequest.QueriesPerRun(CounterBits);

    /// <summary>The mean a readout stands for.</summary>
    public static double MeanOfReadout(int readout, int counterBits) => Math.Clamp(Math.Pow(Math.Sin(Math.PI * readout / (1 << counterBits)), 2), 0, 1);

    public IReadOnlyList<double> Estimate(IReadOnlyList<double[]> values, ICoinEngine engine)
    {
        foreach (var v in values) CoinValues.Check(v);
        var readouts = engine.ReadCounters(values.Select(v => new QssRequest(CoinValues.MeanCoin(v), CounterBits, 1)).ToArray());
        return readouts.Select(r => MeanOfReadout(r[0], CounterBits)).ToArray();
    }
}
