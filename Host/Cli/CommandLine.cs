using System.CommandLine;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Cli;

/// <summary>
/// The `qrt` command line: every command, and the one place that turns failures into exit codes
/// (<see cref="ExitCodes"/>, through <see cref="ErrorReport"/>).
/// </summary>
public static class CommandLine
{
    /// <summary>Shows stack traces, the bridge's output and the Q# call stack of a failure.</summary>
    public static readonly Option<bool> Verbose = new("--verbose")
    {
        Description = "On failure, also print the stack trace, the Q# call stack and the Node bridge's output.",
        Recursive = true,
    };

    public static RootCommand Build()
    {
        var root = new RootCommand("QuantumRayTracing: hybrid quantum-classical ray tracing on the Q# full-state simulator. "
            + "Exit codes: 0 success, 1 usage error, 2 bad input, 3 Q#/QDK/Node bridge failure, 4 internal error, 5 a check failed (bench soak).");
        root.Options.Add(Verbose);
        root.Options.OfType<VersionOption>().Single().Action = new VersionAction();
        root.Subcommands.Add(new RenderCommand());
        root.Subcommands.Add(new SupersampleCommand());
        root.Subcommands.Add(new SearchCommand());
        root.Subcommands.Add(new ScenesCommand());
        root.Subcommands.Add(new BenchCommand());
        root.Subcommands.Add(new EstimateCommand());
        root.Subcommands.Add(new ExportCommand());
        root.Subcommands.Add(new WorkerCommand());
        root.Subcommands.Add(new DocsCommand());
        return root;
    }

    public static int Run(string[] args)
    {
        PlainConsole.ConfigureWhenRedirected();
        var parse = Build().Parse(args);
        // A usage error prints one line, not the whole help text.
        if (parse.Action is System.CommandLine.Invocation.ParseErrorAction onError) onError.ShowHelp = false;
        try
        {
            return parse.Invoke(new InvocationConfiguration { EnableDefaultExceptionHandler = false });
        }
        catch (Exception e)
        {
            var (code, text) = ErrorReport.Describe(e, parse.GetValue(Verbose));
            Console.Error.WriteLine(text);
            return code;
        }
    }
}
