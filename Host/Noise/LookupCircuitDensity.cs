using System.Numerics;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Noise;

/// <summary>
/// The lookup oracle's Grover run (<c>MeasureGroverSearch</c>) evolved exactly as a density matrix under a Pauli channel after
/// every gate on each qubit it touches and before every measurement: the n index qubits and the n − 2 auxiliaries of the
/// Toffoli ladder (<c>ApplyPhaseToAllOnes</c>), gate for gate as the Q# operations apply them. Every gate of the circuit is
/// real and so is PρP† for every Pauli (Y = iXZ gives YρY† = XZρZX), so the matrix stays real. X gates are kept as a
/// relabelling of the basis (a Pauli channel is unchanged by it), so they cost no pass over the matrix. Defined for N a power
/// of two (the preparation is H on every index qubit) whose circuit fits <see cref="MaxQubits"/> qubits: N ≤ 64.
/// </summary>
public static class LookupCircuitDensity
{
    /// <summary>The widest circuit evolved: 10 qubits, a matrix of 2^20 entries (8 MB).</summary>
    public const int MaxQubits = 10;

    /// <summary>Qubits of the run over <paramref name="count"/> indices: the index register and the ladder's auxiliaries.</summary>
    public static int Qubits(int count)
    {
        var n = SearchRegisters.For(count).IndexQubits;
        return n + Auxiliaries(n);
    }

    /// <summary>Whether the run over <paramref name="count"/> indices is evolved here: N a power of two of at most <see cref="MaxQubits"/> qubits.</summary>
    public static bool Evolves(int count) => count >= 1 && BitOperations.IsPow2(count) && Qubits(count) <= MaxQubits;

    /// <summary>
    /// P(the measured index is marked) after r = 0 … <paramref name="maxIterations"/> iterations over <paramref name="marked"/>
    /// under <paramref name="rates"/>; with <paramref name="noisyOutside"/> false the preparation and the measurement are noiseless.
    /// </summary>
    public static double[] MarkedProbabilities(MarkedSet marked, int maxIterations, CircuitRates rates, bool noisyOutside = true)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(maxIterations);
        var evolution = new Evolution(marked, rates, noisyOutside);
        return Enumerable.Range(0, maxIterations + 1).Select(evolution.MarkedProbability).ToArray();
    }

    /// <summary>
    /// A run being evolved: P(marked) after each iteration so far, the matrix kept so that a later question about more
    /// iterations continues it rather than starting again. Safe to ask from several threads.
    /// </summary>
    public sealed class Evolution
    {
        private readonly Run _run;
        private readonly CircuitRates _outside;
        private readonly List<double> _probabilities = [];

        /// <summary>Prepares the run over <paramref name="marked"/>; with <paramref name="noisyOutside"/> false the preparation and measurement are noiseless.</summary>
        public Evolution(MarkedSet marked, CircuitRates rates, bool noisyOutside = true)
        {
            ArgumentNullException.ThrowIfNull(marked);
            ArgumentNullException.ThrowIfNull(rates);
            if (!Evolves(marked.Count)) throw new ArgumentOutOfRangeException(nameof(marked), marked.Count, $"the lookup circuit is evolved for N a power of two up to {MaxQubits} qubits");
            _run = new Run(marked, rates);
            _outside = noisyOutside ? rates : CircuitRates.Noiseless;
            for (var q = 0; q < _run.N; q++) _run.H(q, _outside);
            _probabilities.Add(_run.ReadMarked(_outside));
        }

        /// <summary>P(marked) after <paramref name="iterations"/> iterations, evolving further when asked past the run so far.</summary>
        public double MarkedProbability(int iterations)
        {
            ArgumentOutOfRangeException.ThrowIfNegative(iterations);
            lock (_probabilities)
            {
                while (_probabilities.Count <= iterations)
                {
                    _run.Oracle();
                    _run.Diffusion();
                    _probabilities.Add(_run.ReadMarked(_outside));
                }
                return _probabilities[iterations];
            }
        }
    }

    /// <summary>Noise locations of a run of <paramref name="iterations"/>, as the evolution applies its channels: the closed form's count (<see cref="NoiseLocations"/>).</summary>
    public static long Locations(MarkedSet marked, int iterations) => LocationsByKind(marked, iterations).Sum();

    /// <summary>The same by <see cref="GateKind"/>.</summary>
    public static long[] LocationsByKind(MarkedSet marked, int iterations)
    {
        var run = new Run(marked, CircuitRates.Noiseless, countOnly: true);
        for (var q = 0; q < run.N; q++) run.H(q, CircuitRates.Noiseless);
        for (var r = 0; r < iterations; r++)
        {
            run.Oracle();
            run.Diffusion();
        }
        run.Locations[(int)GateKind.Measurement] += run.N;
        return run.Locations;
    }

    /// <summary>
    /// Which errors harm the run, to first order: per <see cref="GateKind"/>, its locations and their harm-weighted count
    /// −ln Φ / p with depolarizing noise p = 1e-6 on that kind alone (Φ = (P − t/2^n) / (P₀ − t/2^n)); H / L is the kind's harmful
    /// share, the number the old model took as s = 2/3 everywhere. NaN harm where the ideal run reads no better than uniform.
    /// </summary>
    public static IReadOnlyList<(GateKind Kind, long Locations, double Harm)> HarmByKind(MarkedSet marked, int iterations)
    {
        const double p = 1e-6;
        var noise = NoiseModel.Depolarizing(p);
        var locations = LocationsByKind(marked, iterations);
        return Enum.GetValues<GateKind>().Select(kind =>
        {
            var rates = new CircuitRates(kind == GateKind.OneQubit ? noise : NoiseModel.None, kind == GateKind.MultiQubit ? noise : NoiseModel.None, kind == GateKind.Measurement ? noise : NoiseModel.None);
            var fidelity = DepolarizingApproximation.FidelityOf(marked.Count, marked.MarkedCount, iterations, () => MarkedProbabilities(marked, iterations, rates)[iterations]);
            return (kind, locations[(int)kind], fidelity is { } f ? -Math.Log(f) / p : double.NaN);
        }).ToArray();
    }

    /// <summary>Where a noise location sits: after a one-qubit gate (H, X, Z), on a qubit of a gate on two or more (CZ, CCX), or before a measurement.</summary>
    public enum GateKind
    {
        OneQubit,
        MultiQubit,
        Measurement,
    }

    private static int Auxiliaries(int n) => n > 2 ? n - 2 : 0;

    private sealed class Run
    {
        private readonly int _dimension;
        private readonly double[] _rho;
        private readonly int[] _oracleSet;
        private readonly MarkedSet _marked;
        private readonly CircuitRates _rates;
        private readonly bool _countOnly;
        // X gates not yet applied to the matrix: logical basis state = stored state ^ _frame.
        private int _frame;

        public Run(MarkedSet marked, CircuitRates rates, bool countOnly = false)
        {
            _marked = marked;
            _rates = rates;
            _countOnly = countOnly;
            N = SearchRegisters.For(marked.Count).IndexQubits;
            _dimension = 1 << (N + Auxiliaries(N));
            _rho = countOnly ? [] : new double[_dimension * _dimension];
            if (!countOnly) _rho[0] = 1;
            // More than half marked: the complement is marked instead, a global phase, as the Q# operation does.
            _oracleSet = 2 * marked.MarkedCount > marked.Count
                ? Enumerable.Range(0, marked.Count).Where(i => !marked.Contains(i)).ToArray()
                : marked.Indices.ToArray();
        }

        /// <summary>Index qubits n.</summary>
        public int N { get; }

        /// <summary>Noise locations so far (one per qubit per gate, one per measured qubit), by <see cref="GateKind"/>.</summary>
        public long[] Locations { get; } = new long[3];

        private int Auxiliary(int k) => N + k;

        public void Oracle()
        {
            if (_oracleSet.Length == 0) return;
            var allOnes = (1 << N) - 1;
            var previous = 0;
            foreach (var m in _oracleSet)
            {
                var flips = allOnes ^ m;
                Toggle(previous ^ flips);
                PhaseToAllOnes();
                previous = flips;
            }
            Toggle(previous);
        }

        public void Diffusion()
        {
            for (var q = 0; q < N; q++) H(q, _rates);
            Toggle((1 << N) - 1);
            PhaseToAllOnes();
            Toggle((1 << N) - 1);
            for (var q = 0; q < N; q++) H(q, _rates);
        }

        // X on every index qubit whose bit is set, each followed by its channel.
        private void Toggle(int bits)
        {
            _frame ^= bits;
            for (var q = 0; q < N; q++)
                if ((bits >> q & 1) == 1) Channel(q, GateKind.OneQubit);
        }

        private void PhaseToAllOnes()
        {
            if (N == 1)
            {
                Z(0);
            }
            else if (N == 2)
            {
                CZ(0, 1);
            }
            else if (N > 2)
            {
                Toffoli(0, 1, Auxiliary(0));
                for (var k = 2; k <= N - 2; k++) Toffoli(Auxiliary(k - 2), k, Auxiliary(k - 1));
                CZ(Auxiliary(N - 3), N - 1);
                for (var k = N - 2; k >= 2; k--) Toffoli(Auxiliary(k - 2), k, Auxiliary(k - 1));
                Toffoli(0, 1, Auxiliary(0));
            }
        }

        private void Z(int a)
        {
            Negate(1 << a);
            Channel(a, GateKind.OneQubit);
        }

        private void CZ(int a, int b)
        {
            Negate((1 << a) | (1 << b));
            Channel(a, GateKind.MultiQubit);
            Channel(b, GateKind.MultiQubit);
        }

        // ρ → DρD, D = −1 on the basis states where every qubit of mask reads 1 through the pending X's.
        private void Negate(int mask)
        {
            if (_countOnly) return;
            var (dimension, rho, frame) = (_dimension, _rho, _frame);
            var signs = new double[dimension];
            for (var s = 0; s < dimension; s++) signs[s] = ((s ^ frame) & mask) == mask ? -1 : 1;
            Parallel.For(0, dimension, r =>
            {
                var row = r * dimension;
                var c = 0;
                for (; c + Vector<double>.Count <= dimension; c += Vector<double>.Count)
                    (signs[r] * new Vector<double>(rho, row + c) * new Vector<double>(signs, c)).CopyTo(rho, row + c);
                for (; c < dimension; c++) rho[row + c] *= signs[r] * signs[c];
            });
        }

        private void Channel(int q, GateKind kind)
        {
            Locations[(int)kind]++;
            var noise = kind == GateKind.OneQubit ? _rates.OneQubit : _rates.TwoQubit;
            if (_countOnly || noise.PerGate <= 0) return;
            Blocks(q, new BlockMap(BlockKind.Channel, noise.Px + noise.Py, 1 - noise.PerGate - noise.Pz, noise.Px - noise.Py));
        }

        private void Toffoli(int control1, int control2, int target)
        {
            if (_countOnly)
            {
                Locations[(int)GateKind.MultiQubit] += 3;
                return;
            }
            // The target flips where both controls read 1 through the pending X's: swap those rows with their partners, then the columns.
            var (c1, c2, t) = (1 << control1, 1 << control2, 1 << target);
            var pairs = Enumerable.Range(0, _dimension).Where(s => (s & t) == 0 && ((s ^ _frame) & (c1 | c2)) == (c1 | c2)).ToArray();
            var temp = new double[_dimension];
            foreach (var s in pairs)
            {
                var a = _rho.AsSpan(s * _dimension, _dimension);
                var b = _rho.AsSpan((s | t) * _dimension, _dimension);
                a.CopyTo(temp);
                b.CopyTo(a);
                temp.CopyTo(b);
            }
            // The same columns in every row, taken as runs of consecutive columns (most controls are high bits, so the runs are long).
            var runs = new List<(int Start, int Length)>();
            foreach (var s in pairs)
            {
                if (runs.Count > 0 && runs[^1].Start + runs[^1].Length == s) runs[^1] = (runs[^1].Start, runs[^1].Length + 1);
                else runs.Add((s, 1));
            }
            var (dimension, rho) = (_dimension, _rho);
            Parallel.For(0, dimension, r =>
            {
                var row = rho.AsSpan(r * dimension, dimension);
                Span<double> held = stackalloc double[dimension];
                foreach (var (start, length) in runs)
                {
                    var a = row.Slice(start, length);
                    var b = row.Slice(start | t, length);
                    a.CopyTo(held);
                    b.CopyTo(a);
                    held[..length].CopyTo(b);
                }
            });
            foreach (var q in new[] { control1, control2, target })
                Channel(q, GateKind.MultiQubit);
        }

        /// <summary>H on index qubit <paramref name="q"/> (a pending X applied first), then its channel at <paramref name="rates"/>' one-qubit rate.</summary>
        public void H(int q, CircuitRates rates)
        {
            if (!_countOnly)
            {
                if ((_frame >> q & 1) == 1)
                {
                    Blocks(q, new BlockMap(BlockKind.X));
                    _frame ^= 1 << q;
                }
                // H ρ H on each block: a' = (a + b + c + d) / 2, b' = (a − b + c − d) / 2, c' = (a + b − c − d) / 2, d' = (a − b − c + d) / 2; then the channel.
                var noise = rates.OneQubit;
                Blocks(q, new BlockMap(BlockKind.H, noise.Px + noise.Py, 1 - noise.PerGate - noise.Pz, noise.Px - noise.Py));
            }
            Locations[(int)GateKind.OneQubit]++;
        }

        private enum BlockKind { X, H, Channel }

        /// <summary>
        /// One map of 2×2 blocks: X applied to the matrix, or the Pauli channel (after H, for H) ρ → (1 − p) ρ + px XρX + py YρY + pz ZρZ:
        /// on a block [[a, b], [c, d]] X swaps a, d and b, c, Y swaps them and negates b, c, Z negates b, c; so the diagonal pair
        /// mixes at <paramref name="Flip"/> = px + py and the off-diagonal pair is kept at <paramref name="Keep"/> = 1 − p − pz and
        /// exchanged at <paramref name="Swap"/> = px − py. A pending X leaves the channel as it is (it commutes up to a sign that cancels).
        /// </summary>
        private readonly record struct BlockMap(BlockKind Kind, double Flip = 0, double Keep = 0, double Swap = 0);

        // Applies map to every 2×2 block of the matrix over qubit q (rows r0, r0 | bit; columns c0, c0 | bit), rows in parallel.
        private void Blocks(int q, BlockMap map)
        {
            var bit = 1 << q;
            var (dimension, rho) = (_dimension, _rho);
            void Rows(int r0)
            {
                if ((r0 & bit) != 0) return;
                var row0 = r0 * dimension;
                var row1 = (r0 | bit) * dimension;
                if (bit >= Vector<double>.Count && map.Kind != BlockKind.X)
                {
                    VectorRows(row0, row1);
                    return;
                }
                for (var start = 0; start < dimension; start += 2 * bit)
                {
                    for (var c0 = start; c0 < start + bit; c0++)
                    {
                        ref var a = ref rho[row0 + c0];
                        ref var b = ref rho[row0 + c0 + bit];
                        ref var c = ref rho[row1 + c0];
                        ref var d = ref rho[row1 + c0 + bit];
                        if (map.Kind == BlockKind.X)
                        {
                            (a, b, c, d) = (d, c, b, a);
                            continue;
                        }
                        if (map.Kind == BlockKind.H) (a, b, c, d) = ((a + b + c + d) / 2, (a - b + c - d) / 2, (a + b - c - d) / 2, (a - b - c + d) / 2);
                        (a, d, b, c) = ((1 - map.Flip) * a + map.Flip * d, (1 - map.Flip) * d + map.Flip * a, map.Keep * b + map.Swap * c, map.Keep * c + map.Swap * b);
                    }
                }
            }
            // The same on whole vectors where a block's columns c0 and c0 | bit lie in runs of at least a vector's width.
            void VectorRows(int row0, int row1)
            {
                var (flip, keep, swap) = (new Vector<double>(map.Flip), new Vector<double>(map.Keep), new Vector<double>(map.Swap));
                var stay = Vector<double>.One - flip;
                for (var start = 0; start < dimension; start += 2 * bit)
                {
                    for (var c0 = start; c0 < start + bit; c0 += Vector<double>.Count)
                    {
                        var (a, b, c, d) = (new Vector<double>(rho, row0 + c0), new Vector<double>(rho, row0 + c0 + bit), new Vector<double>(rho, row1 + c0), new Vector<double>(rho, row1 + c0 + bit));
                        if (map.Kind == BlockKind.H) (a, b, c, d) = ((a + b + c + d) * 0.5, (a - b + c - d) * 0.5, (a + b - c - d) * 0.5, (a - b - c + d) * 0.5);
                        (stay * a + flip * d).CopyTo(rho, row0 + c0);
                        (stay * d + flip * a).CopyTo(rho, row1 + c0 + bit);
                        (keep * b + swap * c).CopyTo(rho, row0 + c0 + bit);
                        (keep * c + swap * b).CopyTo(rho, row1 + c0);
                    }
                }
            }
            if (dimension >= 256) Parallel.For(0, dimension, Rows);
            else for (var r0 = 0; r0 < dimension; r0++) Rows(r0);
        }

        /// <summary>
        /// P(reading a marked index): the index register's distribution (the auxiliaries summed out), each bit flipped by the
        /// measurement's X or Y at <paramref name="rates"/>' measurement rate and then by the readout error.
        /// </summary>
        public double ReadMarked(CircuitRates rates)
        {
            Locations[(int)GateKind.Measurement] += N;
            var values = 1 << N;
            var distribution = new double[values];
            for (var s = 0; s < _dimension; s++) distribution[(s ^ _frame) & (values - 1)] += _rho[s * _dimension + s];
            var flip = rates.Measurement.Px + rates.Measurement.Py;
            for (var q = 0; q < N; q++)
            {
                // The measurement's flip, then the readout's: a 0 is read as 1 if exactly one of them turns it.
                var zeroAsOne = (1 - flip) * rates.ReadZeroAsOne + flip * (1 - rates.ReadOneAsZero);
                var oneAsZero = (1 - flip) * rates.ReadOneAsZero + flip * (1 - rates.ReadZeroAsOne);
                distribution = MarkedReadout.FlipBit(distribution, q, zeroAsOne, oneAsZero);
            }
            var total = 0.0;
            foreach (var m in _marked.Indices) total += distribution[m];
            return total;
        }
    }
}
