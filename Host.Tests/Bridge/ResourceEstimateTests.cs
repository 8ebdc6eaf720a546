using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Bridge;

public sealed class ResourceEstimateTests(BridgeFixture fixture) : IClassFixture<BridgeFixture>
{
    private readonly QSharpBridge _bridge = fixture.Bridge;

    [Theory]
    [InlineData(8)]
    [InlineData(64)]
    public void OneGroverIterationHasTheQubitsItsRequestNeeds(int count)
    {
        var result = _bridge.Estimate($"QuantumRayTracing.Search.ApplyGroverIterationOnNewRegisters({count}, [1, {count - 2}])");
        var counts = result[0]!["logicalCounts"]!;
        var registers = SearchRegisters.For(count);
        Assert.Equal(registers.PeakQubits, counts["numQubits"]!.GetValue<int>());
        // Two marked indices and one reflection: three multi-controlled Z gates, each made of CCZs.
        Assert.True(counts["cczCount"]!.GetValue<long>() >= 3, counts.ToJsonString());
        Assert.True(result[0]!["physicalCounts"]!["physicalQubits"]!.GetValue<long>() > 0);
    }

    [Fact]
    public void WidthGrowsWithLogOfN()
    {
        int Qubits(int count) => _bridge.Estimate($"QuantumRayTracing.Search.ApplyGroverIterationOnNewRegisters({count}, [0])")[0]!["logicalCounts"]!["numQubits"]!.GetValue<int>();
        var widths = new[] { 16, 256, 4096 }.Select(Qubits).ToArray();
        Assert.Equal([SearchRegisters.For(16).PeakQubits, SearchRegisters.For(256).PeakQubits, SearchRegisters.For(4096).PeakQubits], widths);
        // Each factor of 16 in N adds the same number of qubits: linear in log2 N.
        Assert.Equal(widths[1] - widths[0], widths[2] - widths[1]);
    }
}
