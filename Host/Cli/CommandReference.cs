using System.CommandLine;
using System.CommandLine.Help;
using System.Text;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Cli;

/// <summary>
/// docs/commands.md: every command's `--help`, one section per command, rendered from the parser itself
/// (<see cref="CommandLine.Build"/>) at a fixed width, so the page is the same on any terminal and machine.
/// </summary>
public static class CommandReference
{
    /// <summary>The command that writes the page.</summary>
    public const string CommandText = "qrt docs commands -o docs/commands.md";

    /// <summary>The width the help text is wrapped at, whatever the terminal's.</summary>
    public const int Width = 120;

    /// <summary>The name the program runs under, whatever process builds the parser (a test host has its own).</summary>
    public const string ProgramName = "qrt";

    /// <summary>The marker line the page opens with; a file without it is not replaced.</summary>
    public static string Marker => GeneratedReport.MarkdownMarker("qrt docs commands");

    /// <summary>The page's text: its marker line, then one section per visible command, depth first in the parser's order.</summary>
    public static string Markdown() => new GeneratedReport(null, Marker).Compose(Body());

    /// <summary>The page below its marker line.</summary>
    public static string Body()
    {
        var text = new StringBuilder();
        text.Append("# Commands\n\n");
        text.Append("Every command's `--help`, as the program prints it (`dotnet run --project Host -- COMMAND --help`).\n");
        text.Append("Generated from the command-line parser by `").Append(CommandText).Append("`;\n");
        text.Append("a test fails when an option changes and this page was not regenerated.\n");
        text.Append("What the commands measure and print is in the pages of [docs/](README.md).\n\n");
        var root = ReferenceRoot();
        var paths = Paths(root, []).ToArray();
        foreach (var path in paths.Skip(1))
            text.Append("- [`qrt ").Append(string.Join(' ', path)).Append("`](#").Append(Anchor(path)).Append(")\n");
        foreach (var path in paths)
        {
            text.Append('\n').Append(path.Length == 0 ? "## qrt" : $"## qrt {string.Join(' ', path)}").Append("\n\n");
            text.Append("```text\n").Append(Help(root, path)).Append("```\n");
        }
        return text.ToString();
    }

    /// <summary>The path of every visible command below <paramref name="command"/>, itself first.</summary>
    private static IEnumerable<string[]> Paths(Command command, string[] path)
    {
        yield return path;
        foreach (var sub in command.Subcommands.Where(c => !c.Hidden))
            foreach (var below in Paths(sub, [.. path, sub.Name]))
                yield return below;
    }

    /// <summary>
    /// Takes what this machine decides out of the help, so the page is the same wherever it is generated: the bridges'
    /// default (the core count, which the option's description already says in words) and the widest dense state
    /// the simulator holds here (the machine's own `--help` prints it).
    /// </summary>
    private static void WithoutThisMachine(Command command)
    {
        var here = $"({SimulatorCapacity.DefaultMaxQubits(BridgePool.DefaultWorkers)} qubits here: ";
        foreach (var option in command.Options)
        {
            if (option is Option<int> { Name: "--workers" } workers) workers.DefaultValueFactory = null;
            if (option.Description?.Contains(here, StringComparison.Ordinal) == true)
                option.Description = option.Description.Replace(here, "(`--help` on the machine itself gives the count: ", StringComparison.Ordinal);
        }
        foreach (var sub in command.Subcommands) WithoutThisMachine(sub);
    }

    /// <summary>The anchor GitHub gives the heading "qrt a b": lower case, spaces to hyphens.</summary>
    private static string Anchor(string[] path) => "qrt-" + string.Join('-', path);

    /// <summary>What `qrt PATH --help` prints at <see cref="Width"/> columns, under the program's own name, lines trimmed.</summary>
    public static string Help(string[] path) => Help(ReferenceRoot(), path);

    // The parser as the page shows it: built once per page, without this machine's values, its help at the fixed width.
    private static RootCommand ReferenceRoot()
    {
        var root = CommandLine.Build();
        WithoutThisMachine(root);
        foreach (var help in root.Options.OfType<HelpOption>())
            if (help.Action is HelpAction action) action.MaxWidth = Width;
        return root;
    }

    private static string Help(RootCommand root, string[] path)
    {
        var output = new StringWriter();
        var code = root.Parse([.. path, "--help"]).Invoke(new InvocationConfiguration { Output = output, EnableDefaultExceptionHandler = false });
        if (code != ExitCodes.Success) throw new InvalidOperationException($"'{string.Join(' ', path)} --help' exited with {code}");
        var lines = output.ToString().ReplaceLineEndings("\n").TrimEnd('\n').Split('\n').Select(l => l.TrimEnd()).ToArray();
        // The usage line names the executable, which is the test host's in tests: name the program instead.
        for (var k = 1; k < lines.Length; k++)
            if (lines[k - 1] == "Usage:" && lines[k].StartsWith("  " + root.Name, StringComparison.Ordinal))
                lines[k] = "  " + ProgramName + lines[k][(2 + root.Name.Length)..];
        return string.Join('\n', lines) + "\n";
    }
}
