using System.CommandLine;
using System.CommandLine.Invocation;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Cli;

/// <summary>`qrt --version`: the program's, the QDK's and Node.js's versions (<see cref="ToolVersions.Lines"/>).</summary>
public sealed class VersionAction : SynchronousCommandLineAction
{
    public override int Invoke(ParseResult parseResult)
    {
        foreach (var line in ToolVersions.Detect().Lines()) Console.WriteLine(line);
        return 0;
    }
}
