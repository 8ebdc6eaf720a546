using System.Diagnostics;
using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Tests.Export;

/// <summary>Runs one of Quantum/'s check scripts with node and returns the JSON line it prints.</summary>
internal static class NodeScript
{
    public static JsonNode Run(string script, params string[] arguments)
    {
        var start = new ProcessStartInfo("node") { RedirectStandardOutput = true, RedirectStandardError = true, WorkingDirectory = QuantumProject.Directory };
        start.ArgumentList.Add(Path.Combine(QuantumProject.Directory, script));
        foreach (var argument in arguments) start.ArgumentList.Add(argument);
        using var node = Process.Start(start)!;
        var error = node.StandardError.ReadToEndAsync();
        var output = node.StandardOutput.ReadToEnd();
        node.WaitForExit();
        Assert.True(node.ExitCode == 0, $"{script} failed: {error.Result}");
        return JsonNode.Parse(output.Trim().Split('\n')[^1])!;
    }
}
