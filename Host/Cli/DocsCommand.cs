using System.CommandLine;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `docs`: documentation generated from the program itself. `docs commands` writes docs/commands.md, every
/// command's --help rendered from the parser (<see cref="CommandReference"/>).
/// </summary>
public sealed class DocsCommand : Command
{
    public DocsCommand() : base("docs", "Write documentation generated from the program itself (docs/commands.md).")
    {
        Subcommands.Add(new CommandsCommand());
    }

    private sealed class CommandsCommand : Command
    {
        private readonly Option<FileInfo?> _output = CommonOptions.ReportOutput(
            "Write the page to this file (docs/commands.md), replaced only if this command wrote it. Default: print it.");

        public CommandsCommand() : base("commands", "Every command's --help as one Markdown page, one section per command, at a fixed width.")
        {
            Options.Add(_output);
            SetAction(parse =>
            {
                if (parse.GetValue(_output) is { } file)
                {
                    new GeneratedReport(file.FullName, CommandReference.Marker).Write(CommandReference.Body());
                    Console.WriteLine($"wrote {Path.GetRelativePath(Environment.CurrentDirectory, file.FullName)}");
                }
                else Console.Write(CommandReference.Markdown());
                return ExitCodes.Success;
            });
        }
    }
}
