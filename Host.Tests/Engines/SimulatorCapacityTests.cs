using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Tests.Engines;

public sealed class SimulatorCapacityTests
{
    [Fact]
    public void OneBridgeHoldsTwentyFiveDenseQubitsAndNotTwentySix()
    {
        // Measured: a dense 25-qubit state ran in one bridge, a 26-qubit one exhausted the WebAssembly heap.
        Assert.Equal(25, SimulatorCapacity.MaxQubitsFor(SimulatorCapacity.WebAssemblyHeapBytes));
    }

    [Theory]
    [InlineData(2, 24L << 30, 4L << 30)] // 24 GiB over two workers: the WebAssembly heap binds
    [InlineData(2, 8L << 30, 2L << 30)] // 8 GiB: half of it shared by two workers
    [InlineData(4, 8L << 30, 1L << 30)]
    public void EachWorkerGetsTheSmallerOfItsHeapAndItsShareOfHalfTheMachine(int workers, long machine, long expected) =>
        Assert.Equal(expected, SimulatorCapacity.BytesPerWorker(workers, machine));

    [Fact]
    public void ASmallerShareHoldsFewerQubits() =>
        Assert.Equal(23, SimulatorCapacity.MaxQubitsFor(SimulatorCapacity.BytesPerWorker(4, 8L << 30)));

    [Fact]
    public void RequestsUpToTheLimitPassAndOneQubitMoreIsRefusedWithWhatItNeeds()
    {
        SimulatorCapacity.Check("a search", 13, 12, 13);
        var refused = Assert.Throws<SimulatorLimitException>(() => SimulatorCapacity.Check("a search", 14, 13, 13));
        Assert.Equal("a search needs 14 qubits (2^13 amplitudes, about 640.0 KiB of simulator memory per worker), more than the limit of 13 (--max-qubits; the default is the widest state this machine holds: a WebAssembly heap of at most 4 GiB per worker)", refused.Message);
    }
}
