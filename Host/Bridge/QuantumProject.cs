using System.Reflection;

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
}
