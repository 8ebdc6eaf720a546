using MathNet.Numerics.Distributions;
using QuantumRayTracing.Output;
using QuantumRayTracing.Tests.Output;
using QuantumRayTracing.Tests.Statistics;
using QuantumRayTracing.Tests.Estimation;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>
/// The error of `supersample`'s output image on a synthetic colour image whose means the test knows: 32x32 output
/// pixels of 4x4 subpixels, each channel's subpixels a uniform random level plus small offsets, so the 3072 means
/// spread over [0, 1]. Each item's error is |output level / 255 − exact mean|.
/// </summary>
/// <remarks>
/// Monte Carlo and both QSS forms: the exact expected error of the 8-bit output is summed here over every outcome
/// (binomial counts; the counter's readout distribution written from the QFT sum; for bit planes the convolution of
/// the planes' hit-count estimates), and the image's mean error must lie within 5.73 standard deviations of it
/// (two-sided, false-failure probability 1e-8 under the normal approximation of a mean of 3072 independent
/// bounded errors; the standard deviation is also exact). QCoin and MLAE have no closed form: their mean error
/// must stay below 0.8 and 0.6 times Monte Carlo's exact expected error (the targets are 0.70 and 0.55
/// times Monte Carlo's error at 240 queries, before 8-bit rounding). Over seeds 1-8 this image gave ratios of
/// 0.66 ± 0.011 and 0.516 ± 0.006 (mean ± sd), so the bounds sit 12 and 13 standard deviations above.
/// </remarks>
public sealed class SupersampleErrorTests : IDisposable
{
    private const int Side = 4, Subpixels = Side * Side, Width = 32, Height = 32, Queries = 240;
    private static readonly double Z = Normal.InvCDF(0, 1, 1 - StatisticalBounds.FalseFailure / 2);

    private readonly ScratchDirectory _scratch = new("qrt-supersample-error-");
    private readonly int[][] _levels; // [item = 3·pixel + channel][subpixel]
    private readonly string _input;

    public SupersampleErrorTests()
    {
        var random = new Random(20240917);
        _levels = new int[Width * Height * 3][];
        for (var k = 0; k < _levels.Length; k++)
        {
            var level = random.Next(256);
            _levels[k] = Enumerable.Range(0, Subpixels).Select(_ => Math.Clamp(level + random.Next(-12, 13), 0, 255)).ToArray();
        }
        var image = new RgbImage(Width * Side, Height * Side);
        for (var py = 0; py < Height; py++)
            for (var px = 0; px < Width; px++)
                for (var i = 0; i < Subpixels; i++)
                {
                    var item = 3 * (py * Width + px);
                    image.SetPixel(px * Side + i % Side, py * Side + i / Side, (byte)_levels[item][i], (byte)_levels[item + 1][i], (byte)_levels[item + 2][i]);
                }
        _input = Path.Combine(_scratch.Path, "synthetic.png");
        PngWriter.Write(image, _input);
    }

    public void Dispose() => _scratch.Dispose();

    private double Mean(int item) => _levels[item].Sum() / (255.0 * Subpixels);

    /// <summary>The 8-bit level an estimate is written as: clamped, times 255, rounded half away from zero (<see cref="RgbImage.FromLinear"/>).</summary>
    private static int Level(double estimate) => (int)Math.Round(Math.Clamp(estimate, 0, 1) * 255, MidpointRounding.AwayFromZero);

    private double[] ObservedErrors(string method, params string[] extra)
    {
        var output = Path.Combine(_scratch.Path, $"{method}-{extra.Length}.png");
        var (code, error) = ConsoleCapture.Run(["supersample", "--image", _input, "--subpixels", $"{Side}", "-m", method, .. extra, "--seed", "5", "-o", output]);
        Assert.True(code == 0, error);
        var pixels = ImageReader.Read(output).Pixels.ToArray();
        return Enumerable.Range(0, _levels.Length).Select(k => Math.Abs(pixels[k] / 255.0 - Mean(k))).ToArray();
    }

    /// <summary>Mean and variance of |Level(estimate) / 255 − f| over an estimate's outcome distribution.</summary>
    private static (double Mean, double Variance) Moments(IEnumerable<(double Estimate, double Probability)> outcomes, double f)
    {
        var (m1, m2) = (0.0, 0.0);
        foreach (var (estimate, p) in outcomes)
        {
            var e = Math.Abs(Level(estimate) / 255.0 - f);
            m1 += p * e;
            m2 += p * e * e;
        }
        return (m1, m2 - m1 * m1);
    }

    private void AssertWithinExactError(double[] observed, Func<int, (double Mean, double Variance)> exact, string what)
    {
        var moments = Enumerable.Range(0, observed.Length).Select(exact).ToArray();
        var expected = moments.Average(m => m.Mean);
        var sd = Math.Sqrt(moments.Sum(m => m.Variance)) / observed.Length;
        var mean = observed.Average();
        Assert.True(Math.Abs(mean - expected) <= Z * sd,
            $"{what}: mean output error {mean:0.000000}, exact expectation {expected:0.000000} ± {Z * sd:0.000000} ({Z:0.00} sd, false-failure {StatisticalBounds.FalseFailure})");
    }

    private double MonteCarloExpected(int item) => MonteCarloMoments(item).Mean;

    private (double Mean, double Variance) MonteCarloMoments(int item)
    {
        var f = Mean(item);
        var binomial = new Binomial(f, Queries);
        return Moments(Enumerable.Range(0, Queries + 1).Select(x => ((double)x / Queries, binomial.Probability(x))), f);
    }

    [Fact]
    public void MonteCarloErrorIsItsExactExpectation() =>
        AssertWithinExactError(ObservedErrors("mc"), MonteCarloMoments, "mc, 240 queries");

    [Fact]
    public void ContinuousQssErrorIsItsExactExpectation()
    {
        const int t = 7;
        AssertWithinExactError(ObservedErrors("qss", "--qss-values", "continuous"), item =>
        {
            var f = Mean(item);
            var readout = Readout(f, t);
            return Moments(readout.Select((p, y) => (Math.Pow(Math.Sin(Math.PI * y / (1 << t)), 2), p)), f);
        }, "qss continuous, t = 7");
    }

    [Fact]
    public void BitPlaneQssErrorIsItsExactExpectation()
    {
        const int t = 4;
        // Each readout's hit count: its row's most likely one, the first on a tie (thesis listing 3.1).
        var columns = Enumerable.Range(0, Subpixels + 1).Select(h => FullStateCoinEngineTests.ExactReadout((double)h / Subpixels, t)).ToArray();
        var hitsOf = Enumerable.Range(0, 1 << t).Select(y => Enumerable.Range(0, Subpixels + 1).MaxBy(h => (columns[h][y], -h))).ToArray();
        AssertWithinExactError(ObservedErrors("qss"), item =>
        {
            // The distribution of S = Σ_b 2^b ĥ_b, plane by plane; the estimate is S / (N · 255).
            var sums = new Dictionary<int, double> { [0] = 1 };
            for (var b = 0; b < 8; b++)
            {
                var h = _levels[item].Count(level => (level >> b & 1) == 1);
                var next = new Dictionary<int, double>();
                foreach (var (s, ps) in sums)
                    for (var y = 0; y < 1 << t; y++)
                    {
                        var p = ps * columns[h][y];
                        if (p < 1e-18) continue;
                        var key = s + (hitsOf[y] << b);
                        next[key] = next.GetValueOrDefault(key) + p;
                    }
                sums = next;
            }
            return Moments(sums.Select(kv => (kv.Key / ((double)Subpixels * 255), kv.Value)), Mean(item));
        }, "qss bit planes, t = 4");
    }

    [Theory]
    [InlineData("qcoin", 0.8)]
    [InlineData("mlae", 0.6)]
    public void QuantumEstimatorsBeatMonteCarloByTheTargetMargin(string method, double ratio)
    {
        var observed = ObservedErrors(method).Average();
        var monteCarlo = Enumerable.Range(0, _levels.Length).Average(MonteCarloExpected);
        Assert.True(observed <= ratio * monteCarlo, $"{method}: mean output error {observed:0.000000} above {ratio} x Monte Carlo's exact {monteCarlo:0.000000}");
    }

    /// <summary>The counter's readout distribution: ½|Σ_j e^{2πij(y/P ∓ θ/π)}/P|² per branch, each sum in closed form.</summary>
    private static double[] Readout(double mean, int counterBits)
    {
        var size = 1 << counterBits;
        var omega = Math.Asin(Math.Sqrt(mean)) / Math.PI;
        double Branch(double x)
        {
            var denominator = size * Math.Sin(Math.PI * x);
            return Math.Abs(denominator) < 1e-12 ? 1 : Math.Pow(Math.Sin(size * Math.PI * x) / denominator, 2);
        }
        return Enumerable.Range(0, size).Select(y => 0.5 * Branch((double)y / size - omega) + 0.5 * Branch((double)y / size + omega)).ToArray();
    }
}
