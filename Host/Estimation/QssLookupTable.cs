namespace QuantumRayTracing.Estimation;

/// <summary>
/// The QSS lookup table of thesis 004 (sec. 1.5.2, 2.3.1, listing 3.1): for N binary subpixels and t counter
/// bits, the probability of each counter readout y (row) for each true hit count h = 0..N (column). A readout
/// maps to the hit count of its row's largest entry (the first on a tie), and its confidence is row max /
/// row total (sec. 1.5.3, listing 3.3).
/// </summary>
public sealed class QssLookupTable
{
    public QssLookupTable(int subpixels, int counterBits, double[,] probabilities, string source)
    {
        if (probabilities.GetLength(0) != 1 << counterBits || probabilities.GetLength(1) != subpixels + 1)
            throw new ArgumentException($"a table for {subpixels} subpixels and {counterBits} counter bits has {1 << counterBits} x {subpixels + 1} entries");
        Subpixels = subpixels;
        CounterBits = counterBits;
        Probabilities = probabilities;
        Source = source;
        HitsOfReadout = new int[Readouts];
        ConfidenceOfReadout = new double[Readouts];
        for (var y = 0; y < Readouts; y++)
        {
            var (best, max, total) = (0, 0.0, 0.0);
            for (var h = 0; h <= subpixels; h++)
            {
                total += probabilities[y, h];
                if (probabilities[y, h] > max) (best, max) = (h, probabilities[y, h]);
            }
            HitsOfReadout[y] = best;
            // A readout no hit count produces carries no evidence: confidence 0.
            ConfidenceOfReadout[y] = total > 0 ? max / total : 0;
        }
    }

    public int Subpixels { get; }

    public int CounterBits { get; }

    public int Readouts => 1 << CounterBits;

    /// <summary>[readout y, hit count h] = P(y | h).</summary>
    public double[,] Probabilities { get; }

    /// <summary>How the table was built: "exact" (closed form) or "fullstate, S shots per column".</summary>
    public string Source { get; }

    public int[] HitsOfReadout { get; }

    public double[] ConfidenceOfReadout { get; }

    /// <summary>The table from the closed-form readout distribution, P(y | h) with sin²θ = h/N.</summary>
    public static QssLookupTable Exact(int subpixels, int counterBits)
    {
        Check(subpixels, counterBits);
        var table = new double[1 << counterBits, subpixels + 1];
        for (var h = 0; h <= subpixels; h++)
        {
            var column = CoinProbability.QssReadout((double)h / subpixels, counterBits);
            for (var y = 0; y < column.Length; y++) table[y, h] = column[y];
        }
        return new QssLookupTable(subpixels, counterBits, table, "exact");
    }

    /// <summary>
    /// The table measured by running the QSS circuit on <paramref name="engine"/>, <paramref name="shots"/> times for
    /// every hit count h (the first h subpixels lit): each column is the readouts' relative frequencies. One engine batch.
    /// </summary>
    public static QssLookupTable Measure(int subpixels, int counterBits, ICoinEngine engine, int shots)
    {
        Check(subpixels, counterBits);
        ArgumentOutOfRangeException.ThrowIfLessThan(shots, 1);
        var requests = Enumerable.Range(0, subpixels + 1)
            .Select(h => new QssRequest(Enumerable.Range(0, subpixels).Select(i => i < h ? 1.0 : 0.0).ToArray(), counterBits, shots))
            .ToArray();
        var readouts = engine.ReadCounters(requests);
        var table = new double[1 << counterBits, subpixels + 1];
        for (var h = 0; h <= subpixels; h++)
            foreach (var y in readouts[h]) table[y, h] += 1.0 / shots;
        return new QssLookupTable(subpixels, counterBits, table, $"{engine.Name}, {shots} shots per column");
    }

    public static void Check(int subpixels, int counterBits)
    {
        if (subpixels < 1 || subpixels > 1 << 12) throw new ArgumentOutOfRangeException(nameof(subpixels), subpixels, "a QSS table takes 1 to 4096 subpixels");
        if (counterBits < 1 || counterBits > 12) throw new ArgumentOutOfRangeException(nameof(counterBits), counterBits, "a QSS table takes 1 to 12 counter bits");
    }
}
