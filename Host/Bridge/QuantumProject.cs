using System.Reflection;
using System.Text.Json.Nodes;

namespace QuantumRayTracing.Bridge;

/// <summary>Where the Q# project (bridge.mjs, src/, node_modules/) is: set at build time, overridable by QRT_QUANTUM_DIR.</summary>
public static class QuantumProject
{
    public const string DirectoryVariable = "QRT_QUANTUM_DIR";

    public static string Directory
    {
        get
        {
            var overridden = Environment.GetEnvironmentVariable(DirectoryVariable);
            if (!string.IsNullOrEmpty(overridden)) return overridden;
            return typeof(QuantumProject).Assembly.GetCustomAttributes<AssemblyMetadataAttribute>()
                .First(a => a.Key == "QuantumProjectDirectory").Value!;
        }
    }

    public static string BridgeScript => Path.Combine(Directory, "bridge.mjs");

    /// <summary>The qsharp-lang version package.json beside <paramref name="script"/> pins, or null when there is none.</summary>
    public static string? PinnedQSharpVersion(string script)
    {
        var manifest = Path.Combine(Path.GetDirectoryName(script)!, "package.json");
        if (!File.Exists(manifest)) return null;
        return JsonNode.Parse(File.ReadAllText(manifest))?["dependencies"]?["qsharp-lang"]?.GetValue<string>();
    }
}
