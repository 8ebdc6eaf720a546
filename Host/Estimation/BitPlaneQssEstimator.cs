namespace QuantumRayTracing.Estimation;

/// <summary>
/// QSS on colour by bit planes (thesis 004 sec. 1.6): each subpixel value is quantised to P bits,
/// q_i = round(F(i)·(2^P − 1)); bit b of every q_i makes a binary subpixel image (plane b) whose hit count h_b
/// QSS reads through the lookup table (one run per plane); the estimate is Σ_b 2^b ĥ_b / (N(2^P − 1)), which is
/// the exact mean of the quantised values when every plane is read right. With P = 8 and 8-bit inputs the
/// quantisation is exact.
/// </summary>
/// <remarks>
/// Confidence (thesis sec. 1.5.3, listing 3.3): plane b's readout row gives c_b = row max / row total; a pixel's
/// confidence weights the planes by their significance, Σ_b 2^b c_b / (2^P − 1), so an unsure high plane
/// lowers it as much as the error it can cause. Queries: P runs of 2^(t+1) − 1.
/// </remarks>
public sealed class BitPlaneQssEstimator : IMeanEstimator
{
    public BitPlaneQssEstimator(QssLookupTable table, int planes)
    {
        if (planes < 1 || planes > 16) throw new ArgumentOutOfRangeException(nameof(planes), planes, "QSS takes 1 to 16 bit planes");
        Table = table;
        Planes = planes;
    }

    public QssLookupTable Table { get; }

    /// <summary>P, bits per quantised value.</summary>
    public int Planes { get; }

    public string Name => $"qss (t = {Table.CounterBits}, {Planes} bit planes)";

    public long Queries => Planes * QssRequest.QueriesPerRun(Table.CounterBits);

    public IReadOnlyList<double> Estimate(IReadOnlyList<double[]> values, ICoinEngine engine) => Run(values, engine).Estimates;

    /// <summary>The estimate and the confidence of each item.</summary>
    public (double[] Estimates, double[] Confidence) Run(IReadOnlyList<double[]> values, ICoinEngine engine)
    {
        var top = (1 << Planes) - 1;
        var requests = new List<QssRequest>(values.Count * Planes);
        foreach (var v in values)
        {
            CoinValues.Check(v);
            if (v.Length != Table.Subpixels) throw new ArgumentException($"the lookup table is for {Table.Subpixels} subpixels, an item has {v.Length}");
            var quantised = v.Select(f => (int)Math.Round(f * top, MidpointRounding.AwayFromZero)).ToArray();
            for (var b = 0; b < Planes; b++)
                requests.Add(new QssRequest(quantised.Select(q => (q >> b & 1) == 1 ? 1.0 : 0.0).ToArray(), Table.CounterBits, 1));
        }
        var readouts = engine.ReadCounters(requests);
        var estimates = new double[values.Count];
        var confidence = new double[values.Count];
        for (var j = 0; j < values.Count; j++)
        {
            var (sum, weight) = (0.0, 0.0);
            for (var b = 0; b < Planes; b++)
            {
                var y = readouts[j * Planes + b][0];
                sum += (double)(1 << b) * Table.HitsOfReadout[y];
                weight += (double)(1 << b) * Table.ConfidenceOfReadout[y];
            }
            estimates[j] = Math.Clamp(sum / ((double)Table.Subpixels * top), 0, 1);
            confidence[j] = weight / top;
        }
        return (estimates, confidence);
    }
}
