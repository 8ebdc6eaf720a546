using QuantumRayTracing.Export;

namespace QuantumRayTracing.Tests.Export;

/// <summary>The depth an exported file's header gives: steps as early as their qubits allow, feedback after its measurement.</summary>
public sealed class CircuitDepthTests
{
    [Fact]
    public void GatesOnDisjointQubitsShareALayer()
    {
        // h q0 | x q2 in layer 1, cx q0 q1 in layer 2, ccx q1 q2 q3 in layer 3; x q4 stays in layer 1.
        var circuit = new QirCircuit(5, [new GateStep("h", [0]), new GateStep("x", [2]), new GateStep("cx", [0, 1]),
            new GateStep("ccx", [1, 2, 3]), new GateStep("x", [4])], [0]);
        Assert.Equal(3, CircuitDepth.Of(circuit));
    }

    [Fact]
    public void FeedbackWaitsForTheMeasurementItReads()
    {
        // h q0 (1), measure q0 (2); the branch on its result acts on q2 and q3, idle until then: cz in layer 3, not 1.
        var circuit = new QirCircuit(4, [new GateStep("h", [0]), new MeasureStep(0, 0), new ConditionalStep(0, [new GateStep("cz", [2, 3])])], [0]);
        Assert.Equal(3, CircuitDepth.Of(circuit));
        // Without the branch the circuit is two layers deep.
        Assert.Equal(2, CircuitDepth.Of(circuit with { Steps = circuit.Steps.Take(2).ToArray() }));
    }
}
