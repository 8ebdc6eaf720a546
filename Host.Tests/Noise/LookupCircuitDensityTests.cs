using System.Numerics;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Noise;

/// <summary>The lookup circuit's exact density-matrix evolution: no bridge.</summary>
public class LookupCircuitDensityTests
{
    [Theory]
    [InlineData(2, new[] { 1 })]
    [InlineData(4, new[] { 0 })]
    [InlineData(8, new[] { 5 })]
    [InlineData(8, new[] { 0, 1, 2, 4, 5, 6, 7 })]
    [InlineData(16, new[] { 3, 9 })]
    [InlineData(64, new[] { 5, 17, 40 })]
    public void NoiselessEvolutionIsGroversClosedFormAndCountsTheClosedFormsLocations(int count, int[] marked)
    {
        var set = new MarkedSet(count, marked);
        var probabilities = LookupCircuitDensity.MarkedProbabilities(set, 4, CircuitRates.Noiseless);
        for (var r = 0; r <= 4; r++)
        {
            Assert.Equal(GroverProbability.OfMarked(count, marked.Length, r), probabilities[r], 1e-10);
            Assert.Equal(NoiseLocations.PrepareAndMeasure(count) + r * NoiseLocations.LookupIteration(set), LookupCircuitDensity.Locations(set, r));
        }
    }

    [Theory]
    [InlineData(8, new[] { 5 }, 0.01, 0.02, 0.005)]
    [InlineData(8, new[] { 1, 2, 5 }, 0.003, 0.003, 0.003)]
    [InlineData(4, new[] { 2 }, 0.02, 0.0, 0.03)]
    public void EvolutionMatchesAComplexDensityMatrixBuiltGateByGate(int count, int[] marked, double px, double py, double pz)
    {
        // The reference builds every gate as a complex matrix on the whole register (auxiliary last), applies U ρ U† and the
        // Pauli channel as its Kraus sum Σ p_P P ρ P† after each gate on each qubit it touches, and before the measurement:
        // nothing it shares with the evolution but the gate list of MeasureGroverSearch, written out again below.
        var noise = new NoiseModel(px, py, pz);
        var evolved = LookupCircuitDensity.MarkedProbabilities(new MarkedSet(count, marked), 3, CircuitRates.Of(noise));
        for (var r = 0; r <= 3; r++)
            Assert.Equal(Reference.MarkedProbability(count, marked, r, noise), evolved[r], 1e-12);
    }

    [Fact]
    public void DeviceRatesSplitGateNoiseByArityAndReadTheBitsThroughTheReadoutError()
    {
        var set = new MarkedSet(16, [3, 9]);
        // Equal one- and two-qubit rates and a symmetric readout flip q: the same as that rate everywhere with an X before each
        // measurement at q (an X or Y there flips the read bit).
        var device = LookupCircuitDensity.MarkedProbabilities(set, 3, CircuitRates.Of(new DeviceNoiseModel(4e-3, 4e-3, 0.05, 0.05)));
        var pauli = LookupCircuitDensity.MarkedProbabilities(set, 3, new CircuitRates(NoiseModel.Depolarizing(4e-3), NoiseModel.Depolarizing(4e-3), new NoiseModel(0.05, 0, 0)));
        for (var r = 0; r <= 3; r++) Assert.Equal(pauli[r], device[r], 1e-12);
        // Two-qubit noise alone harms less than the same rate on every gate, and more than none.
        var twoOnly = LookupCircuitDensity.MarkedProbabilities(set, 2, CircuitRates.Of(new DeviceNoiseModel(0, 1e-2)))[2];
        var both = LookupCircuitDensity.MarkedProbabilities(set, 2, CircuitRates.Of(new DeviceNoiseModel(1e-2, 1e-2)))[2];
        Assert.InRange(twoOnly, both + 0.01, GroverProbability.OfMarked(16, 2, 2) - 0.01);
    }

    [Theory]
    [InlineData(8, 5, 2)]
    [InlineData(16, 3, 3)]
    public void HarmByKindAddsUpToTheWholeRunsFirstOrderHarmAndReadsTheMeasurementsBitFlips(int count, int marked, int iterations)
    {
        var set = new MarkedSet(count, [marked]);
        var kinds = LookupCircuitDensity.HarmByKind(set, iterations);
        Assert.Equal(LookupCircuitDensity.Locations(set, iterations), kinds.Sum(k => k.Locations));
        // First order: the kinds' harms add up to the whole run's, noise everywhere at p = 1e-6.
        var (p, uniform, ideal) = (1e-6, 1.0 / count, GroverProbability.OfMarked(count, 1, iterations));
        var whole = LookupCircuitDensity.MarkedProbabilities(set, iterations, CircuitRates.Of(NoiseModel.Depolarizing(p)))[iterations];
        Assert.Equal(-Math.Log((whole - uniform) / (ideal - uniform)) / p, kinds.Sum(k => k.Harm), 0.01);
        // Before the measurement an X or Y (2p/3) flips one of the n read bits: the marked index is read as one of its n neighbours,
        // and n of the N − 1 unmarked ones, each read with (1 − P₀)/(N − 1), are read as the marked one. So
        // H = (2/3) · n · (P₀ − (1 − P₀)/(N − 1)) / (P₀ − 1/N).
        var n = SearchRegisters.For(count).IndexQubits;
        var measurement = Assert.Single(kinds, k => k.Kind == LookupCircuitDensity.GateKind.Measurement);
        Assert.Equal(n, measurement.Locations);
        Assert.Equal(2.0 / 3 * n * (ideal - (1 - ideal) / (count - 1)) / (ideal - uniform), measurement.Harm, 1e-3);
    }

    /// <summary>A complex density matrix over the index register and the ladder's auxiliaries, every gate a full matrix.</summary>
    private static class Reference
    {
        public static double MarkedProbability(int count, int[] marked, int iterations, NoiseModel noise)
        {
            var n = SearchRegisters.For(count).IndexQubits;
            var qubits = n + (n > 2 ? n - 2 : 0);
            var d = 1 << qubits;
            var rho = new Complex[d, d];
            rho[0, 0] = 1;
            void Apply(Complex[,] u, params int[] touched)
            {
                rho = Multiply(Multiply(u, rho), Adjoint(u));
                foreach (var q in touched) rho = Channel(rho, q, noise, d);
            }
            void H(int q) => Apply(Single(q, d, [[1 / Math.Sqrt(2), 1 / Math.Sqrt(2)], [1 / Math.Sqrt(2), -1 / Math.Sqrt(2)]]), q);
            void X(int q) => Apply(Single(q, d, [[0, 1], [1, 0]]), q);
            void Phase()
            {
                if (n == 1) Apply(Single(0, d, [[1, 0], [0, -1]]), 0);
                else if (n == 2) Apply(PhaseOnOnes(d, [0, 1]), 0, 1);
                else
                {
                    var ladder = new List<(int, int, int)> { (0, 1, n) };
                    for (var k = 2; k <= n - 2; k++) ladder.Add((n + k - 2, k, n + k - 1));
                    foreach (var (a, b, t) in ladder) Apply(Toffoli(d, a, b, t), a, b, t);
                    Apply(PhaseOnOnes(d, [n + n - 3, n - 1]), n + n - 3, n - 1);
                    for (var k = ladder.Count - 1; k >= 0; k--) Apply(Toffoli(d, ladder[k].Item1, ladder[k].Item2, ladder[k].Item3), ladder[k].Item1, ladder[k].Item2, ladder[k].Item3);
                }
            }
            var oracle = 2 * marked.Length > count ? Enumerable.Range(0, count).Except(marked).ToArray() : marked;
            for (var q = 0; q < n; q++) H(q);
            for (var j = 0; j < iterations; j++)
            {
                // ApplyMarkingOracle: X where an index's pattern (its zero bits) differs from the previous index's, the phase; then back.
                var previous = 0;
                foreach (var m in oracle)
                {
                    var pattern = ((1 << n) - 1) ^ m;
                    for (var q = 0; q < n; q++) if (((previous ^ pattern) >> q & 1) == 1) X(q);
                    Phase();
                    previous = pattern;
                }
                for (var q = 0; q < n; q++) if ((previous >> q & 1) == 1) X(q);
                for (var q = 0; q < n; q++) H(q);
                for (var q = 0; q < n; q++) X(q);
                Phase();
                for (var q = 0; q < n; q++) X(q);
                for (var q = 0; q < n; q++) H(q);
            }
            for (var q = 0; q < n; q++) rho = Channel(rho, q, noise, d);
            var total = 0.0;
            for (var s = 0; s < d; s++) if (marked.Contains(s & ((1 << n) - 1))) total += rho[s, s].Real;
            return total;
        }

        private static Complex[,] Single(int q, int d, double[][] m)
        {
            var u = new Complex[d, d];
            for (var s = 0; s < d; s++)
            {
                var bit = s >> q & 1;
                for (var b = 0; b < 2; b++) u[s & ~(1 << q) | b << q, s] += m[b][bit];
            }
            return u;
        }

        private static Complex[,] Toffoli(int d, int a, int b, int t)
        {
            var u = new Complex[d, d];
            for (var s = 0; s < d; s++) u[(s >> a & 1) == 1 && (s >> b & 1) == 1 ? s ^ 1 << t : s, s] = 1;
            return u;
        }

        private static Complex[,] PhaseOnOnes(int d, int[] qubits)
        {
            var u = new Complex[d, d];
            for (var s = 0; s < d; s++) u[s, s] = qubits.All(q => (s >> q & 1) == 1) ? -1 : 1;
            return u;
        }

        private static Complex[,] Channel(Complex[,] rho, int q, NoiseModel noise, int d)
        {
            var x = Single(q, d, [[0, 1], [1, 0]]);
            var z = Single(q, d, [[1, 0], [0, -1]]);
            var y = Scale(Multiply(x, z), Complex.ImaginaryOne * -1);
            var result = Scale(rho, 1 - noise.PerGate);
            foreach (var (p, pauli) in new[] { (noise.Px, x), (noise.Py, y), (noise.Pz, z) })
                result = Add(result, Scale(Multiply(Multiply(pauli, rho), Adjoint(pauli)), p));
            return result;
        }

        private static Complex[,] Multiply(Complex[,] a, Complex[,] b)
        {
            var d = a.GetLength(0);
            var c = new Complex[d, d];
            for (var i = 0; i < d; i++)
                for (var k = 0; k < d; k++)
                {
                    if (a[i, k] == Complex.Zero) continue;
                    for (var j = 0; j < d; j++) c[i, j] += a[i, k] * b[k, j];
                }
            return c;
        }

        private static Complex[,] Adjoint(Complex[,] a)
        {
            var d = a.GetLength(0);
            var c = new Complex[d, d];
            for (var i = 0; i < d; i++) for (var j = 0; j < d; j++) c[i, j] = Complex.Conjugate(a[j, i]);
            return c;
        }

        private static Complex[,] Scale(Complex[,] a, Complex k)
        {
            var d = a.GetLength(0);
            var c = new Complex[d, d];
            for (var i = 0; i < d; i++) for (var j = 0; j < d; j++) c[i, j] = k * a[i, j];
            return c;
        }

        private static Complex[,] Add(Complex[,] a, Complex[,] b)
        {
            var d = a.GetLength(0);
            var c = new Complex[d, d];
            for (var i = 0; i < d; i++) for (var j = 0; j < d; j++) c[i, j] = a[i, j] + b[i, j];
            return c;
        }
    }
}
