using System.CommandLine;
using QuantumRayTracing.Cli;

var root = new RootCommand("QuantumRayTracing: hybrid quantum-classical ray tracing on the Q# full-state simulator.");
root.Subcommands.Add(new SearchCommand());
var parse = root.Parse(args);
// A usage error prints one line, not the whole help text.
if (parse.Action is System.CommandLine.Invocation.ParseErrorAction onError) onError.ShowHelp = false;
return parse.Invoke();
