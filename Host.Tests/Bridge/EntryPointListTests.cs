using System.Reflection;
using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Tests.Bridge;

/// <summary>
/// The host's Q# names are the list the Q# build checks (Quantum/entry-points.json): the build fails
/// when a listed name is not in the sources, and this test when the C# constants leave the list.
/// </summary>
public sealed class EntryPointListTests
{
    private static readonly JsonNode List = JsonNode.Parse(File.ReadAllText(Path.Combine(QuantumProject.Directory, "entry-points.json")))!;

    [Fact]
    public void TheOperationsAreTheListedOnes() =>
        Assert.Equal(Listed("operations"), Constants(typeof(QSharpOperations)));

    [Fact]
    public void TheTypesAreTheListedOnes() =>
        Assert.Equal(Listed("types"), Constants(typeof(QSharpTypes)));

    private static string[] Listed(string group) => List[group]!.AsArray().Select(n => n!.GetValue<string>()).Order(StringComparer.Ordinal).ToArray();

    private static string[] Constants(Type type) => type.GetFields(BindingFlags.Public | BindingFlags.Static)
        .Where(f => f.IsLiteral)
        .Select(f => (string)f.GetRawConstantValue()!)
        .Order(StringComparer.Ordinal)
        .ToArray();
}
