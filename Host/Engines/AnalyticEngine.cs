using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>
/// Samples each request's exact outcome distribution instead of simulating it: a marked index with
/// probability sin²((2r+1)θ), uniform among the marked; otherwise uniform among the unmarked.
/// Deterministic for a given random stream and request order. Under noise, each run is ideal with its
/// fidelity Φ and otherwise reads a uniform index of the register (<see cref="DepolarizingApproximation"/>);
/// under a <see cref="DeviceNoiseModel"/>, Φ from its gates' rates, and each bit of the sampled index then
/// flipped by its readout error from the same stream.
/// </summary>
public sealed class AnalyticEngine(SeededRandom random, NoiseModel? noise = null, DepolarizingApproximation? approximation = null, DeviceNoiseModel? device = null) : IGroverEngine
{
    public string Name => "analytic";

    /// <summary>The noise the runs are sampled under; the ideal model takes the exact path, draw for draw.</summary>
    public NoiseModel Noise { get; } = noise is { QubitLoss: > 0 }
        ? throw new ArgumentException("the analytic engine does not model qubit loss", nameof(noise))
        : device is not null && noise is { IsNoiseless: false } ? throw new ArgumentException("give a Pauli noise model or a device model, not both", nameof(device))
        : noise ?? NoiseModel.None;

    /// <summary>The device model the runs are sampled under instead of <see cref="Noise"/>; null for none.</summary>
    public DeviceNoiseModel? Device { get; } = device;

    public DepolarizingApproximation Approximation { get; } = approximation ?? DepolarizingApproximation.Default;

    // A device model without noise takes the exact path, draw for draw, like the ideal Pauli model.
    private readonly CircuitRates? _deviceRates = device is null or { IsNoiseless: true } ? null : CircuitRates.Of(device);

    private readonly ReadoutFlips? _readout = device is { HasReadoutError: true } ? new ReadoutFlips(device, random) : null;

    public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests)
    {
        var measured = new int[requests.Count];
        for (var k = 0; k < requests.Count; k++)
            measured[k] = Sample(requests[k]);
        return measured;
    }

    private int Sample(GroverRequest request)
    {
        var bits = SearchRegisters.For(request.Marked.Count).IndexQubits;
        var index = SampleRun(request, bits);
        return _readout is null ? index : _readout.ReadBits(index, bits);
    }

    private int SampleRun(GroverRequest request, int bits)
    {
        var set = request.Marked;
        // Under noise a draw is made for every run, whatever its Φ, so the stream does not depend on the model's values.
        var noisy = _deviceRates is not null || !Noise.IsNoiseless;
        if (noisy && random.NextDouble() >= (_deviceRates is { } rates ? Approximation.RunFidelity(rates, request) : Approximation.RunFidelity(Noise, request)))
            return random.NextInt(1 << bits);
        var hitsMarked = random.NextDouble() < GroverProbability.OfMarked(request);
        if (hitsMarked)
            return set.Indices[random.NextInt(set.MarkedCount)];
        // The k-th unmarked index: step past every marked index at or below the candidate.
        var index = random.NextInt(set.Count - set.MarkedCount);
        foreach (var m in set.Indices)
        {
            if (m > index) break;
            index++;
        }
        return index;
    }

    public void Dispose() { }
}
