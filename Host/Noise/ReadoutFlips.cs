using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Noise;

/// <summary>
/// The readout error of a <see cref="DeviceNoiseModel"/> applied to bits a simulator measured clean, with the host's
/// seeded generator: the same seed and measured bits give the same read bits.
/// </summary>
public sealed class ReadoutFlips(DeviceNoiseModel device, SeededRandom random)
{
    /// <summary>The flips of <paramref name="device"/>'s readout error, or null when it has none; a readout error needs <paramref name="random"/>.</summary>
    public static ReadoutFlips? For(DeviceNoiseModel? device, SeededRandom? random) => device is { HasReadoutError: true }
        ? new ReadoutFlips(device, random ?? throw new ArgumentException("a readout error needs the host's seeded generator", nameof(random)))
        : null;

    /// <summary>Heads read from <paramref name="heads"/> true heads in <paramref name="flips"/>: each head kept with 1 − P1, each tail turned with P0.</summary>
    public int ReadHeads(int heads, int flips)
    {
        if (!device.HasReadoutError) return heads;
        var read = 0;
        for (var k = 0; k < heads; k++) if (random.NextDouble() >= device.ReadOneAsZero) read++;
        for (var k = heads; k < flips; k++) if (random.NextDouble() < device.ReadZeroAsOne) read++;
        return read;
    }

    /// <summary>A t-bit value read with each bit flipped independently.</summary>
    public int ReadBits(int value, int bits)
    {
        if (!device.HasReadoutError) return value;
        for (var b = 0; b < bits; b++)
        {
            var flip = ((value >> b) & 1) == 0 ? device.ReadZeroAsOne : device.ReadOneAsZero;
            if (random.NextDouble() < flip) value ^= 1 << b;
        }
        return value;
    }
}
