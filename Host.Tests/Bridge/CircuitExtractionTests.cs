using QuantumRayTracing.Bridge;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Bridge;

/// <summary>The bridge's circuit method (getCircuit) against the Resource Estimator and the modelled registers.</summary>
[Collection(QSharpCollection.Name)]
public sealed class CircuitExtractionTests(FullStateFixture fixture)
{
    private QSharpBridge Bridge => fixture.Engine.Pool.Bridges[0];

    [Theory]
    [InlineData(8)]
    [InlineData(64)]
    public void LookupGroverIterationAgreesWithTheEstimator(int count)
    {
        var expression = $"QuantumRayTracing.Search.ApplyGroverIterationOnNewRegisters({count}, [1, {count - 2}])";
        var circuit = Bridge.Circuit(expression);
        var logical = Bridge.Estimate(expression)[0]!["logicalCounts"]!;
        var native = circuit["native"]!;
        var gates = native["gates"]!.AsObject();
        long Gate(string kind) => gates[kind]?.GetValue<long>() ?? 0;
        // Two independent counts of the same program: the simulated trace and the estimator's.
        Assert.Equal(logical["numQubits"]!.GetValue<int>(), circuit["qubits"]!.GetValue<int>());
        Assert.Equal(SearchRegisters.For(count).PeakQubits, circuit["qubits"]!.GetValue<int>());
        Assert.Equal(logical["cczCount"]!.GetValue<long>(), Gate("CCX") + Gate("CCZ"));
        Assert.Equal(logical["tCount"]!.GetValue<long>(), Gate("T") + Gate("T†"));
        Assert.Equal(logical["measurementCount"]!.GetValue<long>(), native["measurements"]!.GetValue<long>());
        // Three multi-controlled Z gates (two marked indices, one reflection) of n controls each.
        Assert.True(Gate("CCX") >= 3, circuit.ToJsonString());
        Assert.True(native["depth"]!.GetValue<long>() <= native["gateCount"]!.GetValue<long>() + native["resets"]!.GetValue<long>());
    }

    [Fact]
    public void CircuitLargerThanTheLimitIsRefused()
    {
        var error = Assert.Throws<QSharpException>(() =>
            Bridge.Circuit("QuantumRayTracing.Search.ApplyGroverIterationOnNewRegisters(64, [1, 6])", maxOperations: 10));
        Assert.Contains("more than 10 operations", error.Message);
    }

    [Fact]
    public void FailingExpressionIsAQSharpErrorWithItsLocation()
    {
        var error = Assert.Throws<QSharpException>(() => Bridge.Circuit("QuantumRayTracing.Search.MeasureGroverSearch(8, [9], 1)"));
        Assert.Contains("marked index 9 is outside 0..7", error.Message);
        Assert.Contains("MeasureGroverSearch.qs", error.Location);
    }
}
