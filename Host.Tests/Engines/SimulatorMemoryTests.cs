using QuantumRayTracing.Experiments;
using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Tests.Engines;

/// <summary>The memory budget behind --max-qubits, checked against the real simulator.</summary>
public sealed class SimulatorMemoryTests
{
    [Fact]
    public void ADenseStateStaysWithinTheBudgetPerAmplitude()
    {
        // 22 qubits: 4M amplitudes, large enough that the heap's growth granularity is noise (docs/simulator-capacity.md).
        var row = SimulatorMemoryBenchmark.Measure(22);

        Assert.InRange(row.BytesPerAmplitude, 16, SimulatorCapacity.BytesPerAmplitude);
    }
}
