using System.CommandLine;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `export`: our circuits as files other tools run (OpenQASM 2, OpenQASM 3, QIR), each with a header that
/// names it and lists the measured register's ideal outcome probabilities (docs/export.md).
/// </summary>
public sealed class ExportCommand : Command
{
    public ExportCommand() : base("export", "Write a circuit as OpenQASM 2 (unitary), OpenQASM 3 or QIR, with a header naming it and its ideal outcome probabilities (docs/export.md).")
    {
        Subcommands.Add(new ExportSearchCommand());
        Subcommands.Add(new ExportPooledSearchCommand());
        Subcommands.Add(new ExportDeviceExperimentCommand());
        Subcommands.Add(new ExportCoinCommand());
        Subcommands.Add(new ExportQssCommand());
    }
}
