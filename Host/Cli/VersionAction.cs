using System.CommandLine;
using System.CommandLine.Invocation;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Cli;

/// <summary>`qrt --version`: the program's, the QDK's and Node.js's versions, one per line; a missing Node.js is said, not an error.</summary>
public sealed class VersionAction : SynchronousCommandLineAction
{
    public override int Invoke(ParseResult parseResult)
    {
        var versions = ToolVersions.Detect();
        Console.WriteLine($"qrt {versions.Program}");
        Console.WriteLine($"QDK: qsharp-lang {versions.QsharpLang ?? "unknown (no Quantum/package.json found)"}");
        Console.WriteLine(versions.Node is { } node ? $"Node.js: {node}" : $"Node.js: not found: {versions.NodeProblem}");
        return 0;
    }
}
