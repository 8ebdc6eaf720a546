using System.CommandLine;
using QuantumRayTracing.Export;

namespace QuantumRayTracing.Cli;

/// <summary>`export qss`: one QSS run over subpixel values up to the counter's measurement.</summary>
public sealed class ExportQssCommand : Command
{
    private readonly Option<double[]> _values = CommonOptions.CoinValues("The subpixel values QSS averages, each in [0, 1], space-separated (1 to 64 values). Default: none, it is required.", required: true);

    private readonly Option<int?> _counterBits = CommonOptions.CounterBits($"Counter qubits T (1 to {QssExport.MaxCounterBits}): 2^T - 1 controlled Grover operators; a run costs 2^(T+1) - 1 queries (15 at T = 3).",
        QssExport.MaxCounterBits, QssExport.DefaultCounterBits, helpName: "T");

    private readonly ExportOutputOptions _output = new();

    public ExportQssCommand() : base("qss", "One run of quantum supersampling: the counter in uniform superposition, the mean coin over the subpixel values, counter qubit j controlling 2^j Grover operators, the inverse QFT; the counter register measured (the coin register is not).")
    {
        this.AddOptions(_values, _counterBits);
        _output.AddTo(this, parse => QssExport.Subject(parse.GetValue(_values)!, parse.GetValue(_counterBits)!.Value));
    }
}
