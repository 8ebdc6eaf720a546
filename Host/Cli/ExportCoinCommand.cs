using System.CommandLine;
using System.CommandLine.Parsing;
using QuantumRayTracing.Export;

namespace QuantumRayTracing.Cli;

/// <summary>`export coin`: one flip of QCoin's direct coin (--mean) or of the mean coin over subpixel values (--values).</summary>
public sealed class ExportCoinCommand : Command
{
    private readonly Option<double?> _mean = new("--mean")
    {
        Description = "The direct coin: one qubit prepared with head probability F in [0, 1]. Default: none; give --mean or --values.",
        HelpName = "F",
    };

    private readonly Option<double[]> _values = CommonOptions.CoinValues("The mean coin over these subpixel values, each in [0, 1], space-separated (1 to 64 values). Default: none; give --mean or --values.");

    private readonly Option<int> _iterations = new Option<int>("--k")
    {
        Description = "Grover operators k applied to the coin (0 to 64).",
        DefaultValueFactory = _ => 1,
    }.Between(0, 64);

    private readonly ExportOutputOptions _output = new();

    public ExportCoinCommand() : base("coin", "One coin flip of QCoin up to its measurement: the direct coin (--mean F) or the mean coin over subpixel values (--values), after k Grover operators; the coin register measured.")
    {
        this.AddOptions(_mean, _values, _iterations);
        _output.AddTo(this, parse => parse.GetValue(_mean) is { } mean ? CoinExport.Direct(mean, parse.GetValue(_iterations)) : CoinExport.Mean(parse.GetValue(_values)!, parse.GetValue(_iterations)));
        Validators.Add(EnsureOneCoinIsGiven);
    }

    private void EnsureOneCoinIsGiven(CommandResult r)
    {
        var (mean, values) = (r.GetResult(_mean) is not null, r.GetResult(_values) is not null);
        if (mean == values)
        {
            r.AddError("--mean and --values choose the coin: give exactly one");
            return;
        }
        if (mean && r.GetValue(_mean) is not (>= 0 and <= 1)) r.AddError($"--mean must lie in [0, 1], got {r.GetValue(_mean)}");
    }
}
