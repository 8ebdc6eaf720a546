using Xunit.Abstractions;

[assembly: TestCollectionOrderer("QuantumRayTracing.Tests.LongestFirstCollectionOrderer", "Host.Tests")]

namespace QuantumRayTracing.Tests;

/// <summary>
/// Starts the longest test collections first: the shared Q# engine's classes run one after another, so if they
/// started late the suite would end on one core. The rest keep xunit's order.
/// </summary>
public sealed class LongestFirstCollectionOrderer : ITestCollectionOrderer
{
    // The collections that take longest on two cores, longest first (measured with the trx logger).
    private static readonly string[] Longest = ["Q#", ".EstimateCommandTests", ".NoiseAwareMlaeTests", ".SoakTests"];

    public IEnumerable<ITestCollection> OrderTestCollections(IEnumerable<ITestCollection> testCollections) =>
        testCollections.OrderBy(Rank);

    private static int Rank(ITestCollection collection)
    {
        var k = Array.FindIndex(Longest, name => collection.DisplayName == name || collection.DisplayName.EndsWith(name, StringComparison.Ordinal));
        return k < 0 ? Longest.Length : k;
    }
}
