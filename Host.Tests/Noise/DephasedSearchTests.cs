using QuantumRayTracing.Noise;
using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Tests.Noise;

/// <summary>The class-symmetric density-matrix run of <see cref="DephasedSearch"/> against a full K×K one and the closed forms.</summary>
public class DephasedSearchTests
{
    [Theory]
    [InlineData(4, 1, 1)]
    [InlineData(8, 1, 2)]
    [InlineData(16, 2, 2)]
    [InlineData(64, 3, 3)]
    [InlineData(64, 1, 6)]
    public void TheIdealRunIsGroversFormula(int register, int marked, int iterations) =>
        Assert.Equal(GroverProbability.OfMarked(register, marked, iterations),
            DephasedSearch.MarkedProbability(register, marked, iterations, 1, DephasedSearch.Iteration.Ideal), 12);

    [Theory]
    [InlineData(8, 1, 2, 0.7, 0.9)]
    [InlineData(64, 3, 3, 0.5, 0.8)]
    public void WithoutDephasingTheRunIsTheGlobalDepolarizingForm(int register, int marked, int iterations, double perIteration, double outside)
    {
        // Φ = F₀ · F^r of the ideal run, the rest uniform: the form the channels replace.
        var phi = outside * Math.Pow(perIteration, iterations);
        var expected = phi * GroverProbability.OfMarked(register, marked, iterations) + (1 - phi) * marked / register;
        Assert.Equal(expected, DephasedSearch.MarkedProbability(register, marked, iterations, outside, new(perIteration, 1, 1, 1)), 12);
    }

    [Theory]
    [InlineData(8, new[] { 5 }, 2, 0.9, 0.6, 0.8, 0.7)]
    [InlineData(8, new[] { 1, 6 }, 3, 0.95, 0.5, 0.9, 0.3)]
    [InlineData(16, new[] { 0, 7, 9 }, 2, 0.8, 0.2, 0.4, 0.6)]
    public void TheFiveNumbersFollowTheFullDensityMatrix(int register, int[] marked, int iterations, double uniform, double cross, double unmarked, double markedPairs)
    {
        // An independent K×K run: oracle sign, each pair's coherence times its class's survival, mixing, then 2|s⟩⟨s| − I.
        var isMarked = Enumerable.Range(0, register).Select(marked.Contains).ToArray();
        var rho = new double[register, register];
        for (var a = 0; a < register; a++)
            for (var b = 0; b < register; b++)
                rho[a, b] = 1.0 / register;
        for (var j = 0; j < iterations; j++)
        {
            var next = new double[register, register];
            for (var a = 0; a < register; a++)
            {
                for (var b = 0; b < register; b++)
                {
                    var v = rho[a, b] * (isMarked[a] ? -1 : 1) * (isMarked[b] ? -1 : 1);
                    if (a != b) v *= isMarked[a] && isMarked[b] ? markedPairs : isMarked[a] || isMarked[b] ? cross : unmarked;
                    next[a, b] = uniform * v + (a == b ? (1 - uniform) / register : 0);
                }
            }
            var diffusion = new double[register, register];
            for (var a = 0; a < register; a++)
                for (var b = 0; b < register; b++)
                    diffusion[a, b] = 2.0 / register - (a == b ? 1 : 0);
            rho = Multiply(Multiply(diffusion, next), diffusion);
        }
        var expected = marked.Sum(m => rho[m, m]);
        Assert.Equal(expected, DephasedSearch.MarkedProbability(register, marked.Length, iterations, 1, new(uniform, cross, unmarked, markedPairs)), 12);
    }

    private static double[,] Multiply(double[,] a, double[,] b)
    {
        var n = a.GetLength(0);
        var c = new double[n, n];
        for (var i = 0; i < n; i++)
            for (var k = 0; k < n; k++)
                for (var j = 0; j < n; j++)
                    c[i, j] += a[i, k] * b[k, j];
        return c;
    }
}
