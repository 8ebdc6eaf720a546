using System.CommandLine;
using QuantumRayTracing.Export;
using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Cli;

/// <summary>The options every `export` subcommand shares: format, output file, and leave to replace it.</summary>
public sealed class ExportOutputOptions
{
    public readonly Option<ExportFormat> Format = new Option<ExportFormat>("--format")
    {
        Description = "qasm2 (OpenQASM 2.0, unitary: uncomputation by gates), qasm3 (OpenQASM 3.0, with measurement and feedback) or qir (the QDK's QIR, adaptive profile).",
        DefaultValueFactory = _ => ExportFormat.Qasm2,
        HelpName = "qasm2|qasm3|qir",
    }.Choices();

    public readonly Option<FileInfo?> Output = CommonOptions.ReportOutput("Write the circuit to this file; an existing file is replaced only with --force. Default: standard output.");

    public readonly Option<bool> Force = new("--force") { Description = "Replace the -o file if it exists." };

    /// <summary>`--oracle` of the search exports (one ray's and a pool's): the construction, narrow by default.</summary>
    public static Option<string> Oracle() => new Option<string>("--oracle")
    {
        Description = "How the oracle is built. The export clears the loaded registers by a second lookup whatever the construction (the QDK cannot compile the measured unlookup of compact, baseline and device to QIR), so compact exports as narrow.",
        DefaultValueFactory = _ => OracleConstruction.Narrow.Name,
        HelpName = string.Join('|', OracleConstruction.Named.Select(c => c.Name)),
    }.Must(name => OracleConstruction.Named.Any(c => c.Name == name)
        ? null
        : $"--oracle: unknown construction '{name}'; expected {string.Join(", ", OracleConstruction.Named.Select(c => c.Name))}");

    /// <summary>The construction <paramref name="oracle"/> (made by <see cref="Oracle"/>) names.</summary>
    public static OracleConstruction Construction(ParseResult parse, Option<string> oracle) => OracleConstruction.Named.Single(c => c.Name == parse.GetValue(oracle));

    /// <summary>Adds the options and the action: the subject <paramref name="subject"/> reads from the options, written as asked.</summary>
    public void AddTo(Command command, Func<ParseResult, ExportSubject> subject)
    {
        command.AddOptions(Format, Output, Force);
        command.SetAction(parse =>
        {
            ExportRun.Run(new ExportSettings(subject(parse), parse.GetValue(Format), parse.GetValue(Output)?.ToString(), parse.GetValue(Force)), Console.Out);
            return ExitCodes.Success;
        });
    }
}
