using System.CommandLine;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Output;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Cli;

/// <summary>
/// The `qrt` command line: every command, and the one place that turns failures into exit codes —
/// 0 success, 1 usage error, 2 bad input (scene, paths, options), 3 a failure of the QDK or its bridge.
/// </summary>
public static class CommandLine
{
    public const int BadInput = 2;
    public const int QuantumFailure = 3;

    public static RootCommand Build()
    {
        var root = new RootCommand("QuantumRayTracing: hybrid quantum-classical ray tracing on the Q# full-state simulator.");
        root.Subcommands.Add(new RenderCommand());
        root.Subcommands.Add(new SupersampleCommand());
        root.Subcommands.Add(new SearchCommand());
        root.Subcommands.Add(new ScenesCommand());
        root.Subcommands.Add(new BenchCommand());
        root.Subcommands.Add(new EstimateCommand());
        return root;
    }

    public static int Run(string[] args)
    {
        var parse = Build().Parse(args);
        // A usage error prints one line, not the whole help text.
        if (parse.Action is System.CommandLine.Invocation.ParseErrorAction onError) onError.ShowHelp = false;
        try
        {
            return parse.Invoke(new InvocationConfiguration { EnableDefaultExceptionHandler = false });
        }
        catch (Exception e) when (e is UserError or SceneError)
        {
            Console.Error.WriteLine($"error: {e.Message}");
            return BadInput;
        }
        catch (Exception e) when (e is BridgeException or QSharpException)
        {
            Console.Error.WriteLine($"error: {e.Message}");
            return QuantumFailure;
        }
    }
}
