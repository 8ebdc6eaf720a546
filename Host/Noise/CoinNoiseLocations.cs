using System.Numerics;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Noise;

/// <summary>
/// Noise locations (one per qubit per operation, measurements included; <see cref="NoiseLocations"/>) of the
/// supersampling circuits, in closed form from the gates the Q# operations and the standard library's
/// decompositions apply (tested against the circuits the QDK extracts), for any subpixel count N.
/// </summary>
public static class CoinNoiseLocations
{
    /// <summary>
    /// Locations of one flip of a <paramref name="kind"/> coin amplified by <paramref name="iterations"/> Grover
    /// operators: the preparation, the operators and the measurement of every qubit.
    /// </summary>
    public static long Flip(CoinKind kind, IReadOnlyList<double> amplitudes, int iterations) =>
        PrepareAndMeasure(kind, amplitudes) + iterations * GroverOperator(kind, amplitudes);

    /// <summary>Locations of a flip outside its Grover operators: the preparation and the measurement of every qubit.</summary>
    public static long PrepareAndMeasure(CoinKind kind, IReadOnlyList<double> amplitudes)
    {
        ArgumentNullException.ThrowIfNull(amplitudes);
        if (kind == CoinKind.Direct) return 1 + 1; // one Ry, one measurement
        var n = CoinRegisters.SubpixelQubits(amplitudes.Count);
        return PrepareCoin(kind, amplitudes) + n + 1;
    }

    /// <summary>
    /// Locations of one Grover operator −A S₀ A† S_χ of the coin: the head's mark S_χ, the preparation undone, the
    /// reflection about |0…0⟩ (X on every qubit around a multiply controlled Z), the preparation, and the
    /// four gates of the global sign (the direct coin needs neither the X gates nor the sign: A Z A† Z).
    /// </summary>
    public static long GroverOperator(CoinKind kind, IReadOnlyList<double> amplitudes)
    {
        ArgumentNullException.ThrowIfNull(amplitudes);
        if (kind == CoinKind.Direct) return 4;
        var n = CoinRegisters.SubpixelQubits(amplitudes.Count);
        var mark = kind == CoinKind.Shifted ? 2L * n + ControlledZ(n) : 1;
        return mark + 2 * PrepareCoin(kind, amplitudes) + Reflection(n, 0) + 4;
    }

    /// <summary>
    /// Locations of one QSS run with <paramref name="counterBits"/> counter qubits on the mean coin: H on the
    /// counter, the coin prepared, 2^t − 1 Grover operators each under one counter qubit, the register reversal
    /// (⌊t/2⌋ SWAPs), the inverse QFT (t H and t(t − 1)/2 controlled phases of 7 locations each: three Rz and two CX)
    /// and the counter measured.
    /// </summary>
    public static long Qss(IReadOnlyList<double> amplitudes, int counterBits)
    {
        ArgumentNullException.ThrowIfNull(amplitudes);
        ArgumentOutOfRangeException.ThrowIfLessThan(counterBits, 1);
        var n = CoinRegisters.SubpixelQubits(amplitudes.Count);
        var t = (long)counterBits;
        // Under control the X gates of the reflection and of each oracle index stay uncontrolled (within blocks);
        // the marks, the preparation's gates and the sign take the counter qubit as one more control.
        var controlledGrover = ControlledZ(1) + 2 * Prepare(amplitudes, 1) + Reflection(n, 1) + 4 * 2;
        var inverseQft = t + 7 * t * (t - 1) / 2;
        return t + Prepare(amplitudes, 0) + ((1L << counterBits) - 1) * controlledGrover + 2 * (t / 2) + inverseQft + t;
    }

    // A coin's preparation A, never under control: the shifted coin undoes its uniform superposition after the oracle.
    private static long PrepareCoin(CoinKind kind, IReadOnlyList<double> amplitudes) =>
        kind == CoinKind.Shifted
            ? 2 * UniformPreparation(amplitudes.Count, CoinRegisters.SubpixelQubits(amplitudes.Count), 0) + Oracle(amplitudes, 0)
            : Prepare(amplitudes, 0);

    // The mean coin's preparation under `controls` extra controls: the uniform superposition and the oracle.
    private static long Prepare(IReadOnlyList<double> amplitudes, int controls) =>
        UniformPreparation(amplitudes.Count, CoinRegisters.SubpixelQubits(amplitudes.Count), controls) + Oracle(amplitudes, controls);

    /// <summary>
    /// Locations of <c>PrepareUniformSuperposition(count, register)</c> on <paramref name="width"/> qubits under
    /// <paramref name="controls"/> extra controls, following its recursion: a power of two is H on every qubit; a count
    /// above the lower half rotates the top qubit (Ry), spreads the lower half by H under the top qubit's |0⟩ (X on it
    /// before and after, uncontrolled) and prepares the rest under its |1⟩, one control more; a smaller count recurses
    /// on the lower qubits.
    /// </summary>
    public static long UniformPreparation(int count, int width, int controls)
    {
        if (count == 1 << width) return width * ControlledH(controls);
        var lowerHalf = 1 << (width - 1);
        if (count <= lowerHalf) return UniformPreparation(count, width - 1, controls);
        return ControlledRy(controls) + 2 + (width - 1) * ControlledH(controls + 1) + UniformPreparation(count - lowerHalf, width - 1, controls + 1);
    }

    // The shader oracle: per non-zero amplitude a_i, X on the subpixel qubits where i has a 0 bit and back, around
    // an Ry controlled by the n subpixel qubits and `controls` more.
    private static long Oracle(IReadOnlyList<double> amplitudes, int controls)
    {
        var n = CoinRegisters.SubpixelQubits(amplitudes.Count);
        var total = 0L;
        for (var i = 0; i < amplitudes.Count; i++)
            if (Math.Abs(amplitudes[i]) > 0) total += 2L * (n - BitOperations.PopCount((uint)i)) + ControlledRy(n + controls);
        return total;
    }

    // S₀ on the subpixel register and coin: X on all n + 1 qubits and back around Z on the coin controlled by the
    // n subpixel qubits and `controls` more.
    private static long Reflection(int n, int controls) => 2L * (n + 1) + ControlledZ(n + controls);

    /// <summary>
    /// Ry with c controls as the standard library applies it: Ry (1); one control: two Rz, two CX, two H, S and S†
    /// (10); more: the controls' AND computed into auxiliaries by a ladder of c − 1 CCX and undone (6 per control past the first).
    /// </summary>
    public static long ControlledRy(int controls) => controls == 0 ? 1 : 10 + 6L * (controls - 1);

    /// <summary>H with c controls: H (1); otherwise S, H, T, X with the c controls, T†, H, S† (6 and the controlled X).</summary>
    public static long ControlledH(int controls) => controls == 0 ? 1 : 6 + ControlledX(controls);

    /// <summary>X with c controls: X (1), CX (2), CCX (3); more: a ladder of CCX into auxiliaries around one CCX, done and undone.</summary>
    public static long ControlledX(int controls) => controls switch
    {
        0 => 1,
        1 => 2,
        _ => 3 + 6L * (controls - 2),
    };

    /// <summary>Z with c controls: Z (1); CZ (2); more: H on the target around X with the c controls.</summary>
    public static long ControlledZ(int controls) => controls switch
    {
        0 => 1,
        1 => 2,
        _ => 2 + ControlledX(controls),
    };
}
