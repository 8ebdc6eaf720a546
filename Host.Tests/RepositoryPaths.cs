using System.Text.Json.Nodes;

namespace QuantumRayTracing.Tests;

/// <summary>Paths inside the repository, found by walking up from the test binaries to the solution file.</summary>
public static class RepositoryPaths
{
    public static string Root { get; } = FindRoot();

    public static string Scenes => Path.Combine(Root, "Scenes");

    /// <summary>The qsharp-lang version Quantum/package-lock.json installs: the QDK every bridge must report.</summary>
    public static string LockedQdkVersion { get; } =
        JsonNode.Parse(File.ReadAllText(Path.Combine(Root, "Quantum", "package-lock.json")))!["packages"]!["node_modules/qsharp-lang"]!["version"]!.GetValue<string>();

    private static string FindRoot()
    {
        for (var directory = new DirectoryInfo(AppContext.BaseDirectory); directory is not null; directory = directory.Parent)
            if (File.Exists(Path.Combine(directory.FullName, "QuantumRayTracing.sln"))) return directory.FullName;
        throw new InvalidOperationException("QuantumRayTracing.sln not found above " + AppContext.BaseDirectory);
    }
}
