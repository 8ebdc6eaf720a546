using System.Globalization;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Supersampling;

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
                $"coin: one qubit, Ry(2 asin sqrt(f)) with f = {Number(mean)}",
                Grover(amplitude, iterations),
            ],
            $"{QSharpOperations.ApplyDirectCoin}({QSharpDouble(amplitude)}, {iterations.ToString(CultureInfo.InvariantCulture)}, _)",
            1,
            "coin");
    }

    public static ExportSubject Mean(double[] values, int iterations)
    {
        SubpixelValues.Check(values);
        var amplitudes = SubpixelValues.MeanCoin(values);
        var index = (int)Math.Ceiling(Math.Log2(values.Length));
        return new ExportSubject(
            $"QCoin's mean coin over {values.Length} subpixel values, one flip ({Command} --values)",
            [
                $"subpixel values: {string.Join(' ', values.Select(Number))} (mean {Number(SubpixelValues.Mean(values))})",
                $"coin: {index} subpixel qubits in uniform superposition, each value's amplitude sqrt(F(i)) rotated onto the coin qubit; bits 0..{index - 1} of the register are the subpixel index, bit {index} the coin (heads: 1)",
                Grover(CoinProbability.HeadAmplitude(CoinKind.Mean, amplitudes), iterations),
            ],
            $"{QSharpOperations.ApplyMeanCoin}([{string.Join(", ", amplitudes.Select(QSharpDouble))}], {iterations.ToString(CultureInfo.InvariantCulture)}, _)",
            index + 1,
            "coin");
    }

    private static string Grover(double headAmplitude, int iterations) =>
        $"Grover operators k = {iterations}: P(heads) = sin^2((2k+1) theta) = {Number(CoinProbability.Head(headAmplitude, iterations))} by the closed form, sin theta = {Number(headAmplitude)}";

    private static string Number(double value) => value.ToString("R", CultureInfo.InvariantCulture);

    /// <summary>A Q# Double literal holding the value exactly (round-trip digits, always with a point or an exponent).</summary>
    private static string QSharpDouble(double value)
    {
        var text = value.ToString("R", CultureInfo.InvariantCulture);
        return text.Contains('.') || text.Contains('E') ? text : text + ".0";
    }
}
