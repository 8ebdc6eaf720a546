using QuantumRayTracing.Bridge;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using static QuantumRayTracing.Export.ExportNumber;

namespace QuantumRayTracing.Export;

/// <summary>
/// QCoin's coins as exports, one flip each up to its measurement: the direct coin (one qubit prepared with
/// the mean, Q# <c>ApplyDirectCoin</c>) and the mean coin over given subpixel values (Q# <c>ApplyMeanCoin</c>,
/// the flip <c>CountCoinHeads</c> makes), each after k Grover operators.
/// </summary>
public static class CoinExport
{
    private const string Command = "qrt export coin";

    public static ExportSubject Direct(double mean, int iterations)
    {
        var amplitude = Math.Sqrt(mean);
        return new ExportSubject(
            $"QCoin's direct coin, one flip ({Command} --mean)",
            [
                $"coin: one qubit, Ry(2 asin sqrt(f)) with f = {Text(mean)}",
                Grover(amplitude, iterations),
            ],
            $"{QSharpOperations.ApplyDirectCoin}({QSharpDouble(amplitude)}, {Text(iterations)}, _)",
            1,
            "coin");
    }

    public static ExportSubject Mean(double[] values, int iterations)
    {
        CoinValues.Check(values);
        var amplitudes = CoinValues.MeanCoin(values);
        var index = SubpixelQubits(values);
        return new ExportSubject(
            $"QCoin's mean coin over {values.Length} subpixel values, one flip ({Command} --values)",
            [
                ValuesLine(values),
                $"{MeanCoinLine(index)}; bits 0..{index - 1} of the register are the subpixel index, bit {index} the coin (heads: 1)",
                Grover(CoinProbability.HeadAmplitude(CoinKind.Mean, amplitudes), iterations),
            ],
            $"{QSharpOperations.ApplyMeanCoin}({QSharpDoubles(amplitudes)}, {Text(iterations)}, _)",
            index + 1,
            "coin");
    }

    /// <summary>ceil(log2 N): the subpixel register's width for N values (Q# <c>SubpixelQubits</c>).</summary>
    public static int SubpixelQubits(double[] values) => (int)Math.Ceiling(Math.Log2(values.Length));

    /// <summary>The header line listing the subpixel values and their mean.</summary>
    public static string ValuesLine(double[] values) =>
        $"subpixel values: {string.Join(' ', values.Select(v => Text(v)))} (mean {Text(CoinValues.Mean(values))})";

    /// <summary>The header's description of the mean coin's preparation on <paramref name="index"/> subpixel qubits.</summary>
    public static string MeanCoinLine(int index) =>
        $"coin: {ExportHeader.Plural(index, "subpixel qubit")} in uniform superposition, each value's amplitude sqrt(F(i)) rotated onto the coin qubit";

    private static string Grover(double headAmplitude, int iterations) =>
        $"Grover operators k = {iterations}: P(heads) = sin^2((2k+1) theta) = {Text(CoinProbability.Head(headAmplitude, iterations))} by the closed form, sin theta = {Text(headAmplitude)}";
}
