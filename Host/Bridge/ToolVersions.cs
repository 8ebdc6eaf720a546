using System.ComponentModel;
using System.Diagnostics;
using System.Reflection;

namespace QuantumRayTracing.Bridge;

/// <summary>
/// The versions a result depends on: this program's, the QDK's (the qsharp-lang version Quantum/package.json
/// pins) and Node.js's (<c>node --version</c> of the executable the bridge starts). A missing Node.js is a
/// value (<see cref="NodeProblem"/>), not a failure: the versions are asked for to find out what is installed.
/// </summary>
public sealed record ToolVersions(string Program, string? QsharpLang, string? Node, string? NodeProblem)
{
    private static readonly TimeSpan NodeTimeout = TimeSpan.FromSeconds(20);

    /// <summary>This program's version (with the source revision when the build recorded it).</summary>
    public static string ProgramVersion =>
        typeof(ToolVersions).Assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion
        ?? typeof(ToolVersions).Assembly.GetName().Version?.ToString() ?? "unknown";

    /// <summary>What `qrt --version` prints, one version a line; a missing Node.js is said, not an error.</summary>
    public IReadOnlyList<string> Lines() =>
        [$"qrt {Program}", $"QDK: qsharp-lang {QsharpLang ?? "unknown (no Quantum/package.json found)"}", Node is { } node ? $"Node.js: {node}" : $"Node.js: not found: {NodeProblem}"];

    /// <summary>Asks Node.js for its version; the program and QDK versions are read from files.</summary>
    public static ToolVersions Detect(BridgeOptions? options = null)
    {
        options ??= new BridgeOptions();
        var (node, problem) = AskNode(options.Node);
        return new ToolVersions(ProgramVersion, QuantumProject.PinnedQSharpVersion(options.Script), node, problem);
    }

    private static (string? Version, string? Problem) AskNode(string executable)
    {
        var start = new ProcessStartInfo(executable, ["--version"])
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        try
        {
            using var process = Process.Start(start)!;
            var output = process.StandardOutput.ReadToEndAsync();
            _ = process.StandardError.ReadToEndAsync();
            if (!process.WaitForExit(NodeTimeout))
            {
                process.Kill(entireProcessTree: true);
                return (null, $"'{executable} --version' did not answer within {NodeTimeout.TotalSeconds:0} s");
            }
            var version = output.Result.Trim();
            return process.ExitCode == 0 && version.Length > 0
                ? (version, null)
                : (null, $"'{executable} --version' exited with code {process.ExitCode}");
        }
        catch (Win32Exception)
        {
            return (null, $"could not start '{executable}'; install Node.js or set {BridgeOptions.NodeVariable} to its path");
        }
    }
}
