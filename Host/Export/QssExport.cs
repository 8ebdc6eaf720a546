using QuantumRayTracing.Bridge;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using static QuantumRayTracing.Export.ExportNumber;

namespace QuantumRayTracing.Export;

/// <summary>
/// One QSS run as an export (Q# <c>ApplyQss</c>, what <c>MeasureQssReadout</c> runs before it measures): the
/// counter in uniform superposition, the mean coin over the subpixel values, counter qubit j controlling 2^j
/// Grover operators of the coin, the inverse QFT on the counter, and the counter measured. The coin register
/// stays entangled with the counter and is not measured: the header gives the counter's marginal distribution.
/// </summary>
public static class QssExport
{
    public const int DefaultCounterBits = 3;

    /// <summary>
    /// The circuit holds 2^t − 1 controlled Grover operators: at t = 6 and 64 values it is 214,542 gates (22 s to
    /// export); t = 8 takes five minutes and 1.5 GB, so the export stops at 6.
    /// </summary>
    public const int MaxCounterBits = 6;

    public static ExportSubject Subject(double[] values, int counterBits)
    {
        CoinValues.Check(values);
        ArgumentOutOfRangeException.ThrowIfLessThan(counterBits, 1);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(counterBits, MaxCounterBits);
        var amplitudes = CoinValues.MeanCoin(values);
        var index = CoinExport.SubpixelQubits(values);
        var operators = (1 << counterBits) - 1;
        return new ExportSubject(
            $"quantum supersampling (QSS) over {values.Length} subpixel values, one readout of the counter (qrt export qss)",
            [
                CoinExport.ValuesLine(values),
                $"{CoinExport.MeanCoinLine(index)}: qubits {counterBits}..{counterBits + index} of the register, not measured",
                $"counter: t = {counterBits} qubits in uniform superposition, qubit j controlling 2^j Grover operators of the coin ({operators} in all), then the inverse QFT; a run costs 2^(t+1) - 1 = {2 * operators + 1} queries (a coin preparation 1, a Grover operator 2)",
                $"the readout y estimates the mean as sin^2(pi y / 2^t); P(y) = (K(y/2^t - theta/pi) + K(y/2^t + theta/pi)) / 2, K the Fejer kernel of 2^t, sin^2 theta = the mean",
            ],
            $"{QSharpOperations.ApplyQss}({QSharpDoubles(amplitudes)}, {Text(counterBits)}, _)",
            counterBits,
            "counter",
            index + 1);
    }
}
