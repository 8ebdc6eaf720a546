using System.CommandLine;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Output;

var root = new RootCommand("QuantumRayTracing: hybrid quantum-classical ray tracing on the Q# full-state simulator.");
root.Subcommands.Add(new RenderCommand());
root.Subcommands.Add(new SearchCommand());
root.Subcommands.Add(new ScenesCommand());
root.Subcommands.Add(new BenchCommand());

var parse = root.Parse(args);
// A usage error prints one line, not the whole help text.
if (parse.Action is System.CommandLine.Invocation.ParseErrorAction onError) onError.ShowHelp = false;
try
{
    return parse.Invoke(new InvocationConfiguration { EnableDefaultExceptionHandler = false });
}
catch (Exception e) when (e is UserError or QuantumRayTracing.Scenes.SceneError)
{
    Console.Error.WriteLine($"error: {e.Message}");
    return 2;
}
catch (Exception e) when (e is BridgeException or QSharpException)
{
    Console.Error.WriteLine($"error: {e.Message}");
    return 3;
}
