using QuantumRayTracing.Bridge;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>What `bench noise` measures.</summary>
/// <param name="Parts">Any of "exposure" (the gate-level oracle's noise exposure traced per scene shape), "model" (the approximation against the simulator, and the gate-level runs its whole-harm share is fitted on), "supersampling" (the same for the coins and QSS), "device" (fig. 15), "render" (rendering under noise).</param>
/// <param name="Shots">Runs per case of the model checks.</param>
/// <param name="DeviceShots">Measurements per error rate of the device experiment.</param>
/// <param name="Scenes">The scenes rendered under noise, by name.</param>
/// <param name="Size">Pixels per side of the analytic renders.</param>
/// <param name="ConfirmSize">Pixels per side of the confirmation renders on the noisy gate engine; 0 skips them.</param>
/// <param name="ConfirmRates">Per-gate error rates of the confirmation renders.</param>
/// <param name="Workers">Node bridge processes started when <paramref name="Pool"/> is null.</param>
/// <param name="Pool">Bridges the simulator work runs on (a cluster's), used and not stopped; null starts <paramref name="Workers"/> local ones.</param>
/// <param name="ExposureScenes">The scenes whose gate-level circuit the exposure part traces, by name.</param>
/// <param name="ConfirmScene">The small scene of the confirmation renders, by name.</param>
public sealed record NoiseBenchSettings(
    IReadOnlySet<string> Parts,
    int Shots,
    int DeviceShots,
    IReadOnlyList<(string Name, Scene Scene)> Scenes,
    int Size,
    int ConfirmSize,
    IReadOnlyList<double> ConfirmRates,
    int Workers,
    BridgePool? Pool = null,
    IReadOnlyList<(string Name, Scene Scene)>? ExposureScenes = null,
    (string Name, Scene Scene)? ConfirmScene = null)
{
    /// <summary>The scene of the confirmation renders: N = 8, small enough for the noisy gate engine.</summary>
    public const string ConfirmSceneName = "qornell-8";

    public static readonly string[] AllParts = ["exposure", "model", "supersampling", "device", "render"];

    /// <summary>The largest N whose gate-level circuit the exposure part traces (N = 64 takes about a minute).</summary>
    public const int MaxExposurePrimitives = 64;

    /// <summary>
    /// The share of a traced circuit's locations the exposure part grades at <paramref name="primitives"/> (Quantum/noise-harm.mjs
    /// follows each error through the rest of the circuit, so its time grows as the circuit's square): every location up to
    /// N = 16, a random share above, each trace's estimate unbiased and their spread measured.
    /// </summary>
    public static double GradedFraction(int primitives) => primitives switch
    {
        <= 16 => 1,
        <= 32 => 0.5,
        _ => 0.25,
    };

    /// <summary>
    /// Graded traces the exposure part averages per shape: more at N = 8, the shape whose spread the tests take as measured
    /// (Host.Tests GateLevelExposureTests), three elsewhere.
    /// </summary>
    public static int HarmTraces(int primitives) => primitives <= 8 ? 8 : GateLevelExposure.DefaultTraces;

    /// <summary>The scenes the render part uses, from the scene directory.</summary>
    public static readonly string[] RenderScenes = ["qornell-64", "depth-complexity-64"];

    /// <summary>Per-gate error rates of the device experiment.</summary>
    public static readonly double[] DeviceRates = [0, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1];

    /// <summary>Names of the plots the parts draw (each written as &lt;report&gt;-&lt;name&gt;.png).</summary>
    public IEnumerable<string> PlotNames()
    {
        if (Parts.Contains("model")) yield return "model-check";
        if (Parts.Contains("supersampling")) yield return "supersampling-check";
        if (Parts.Contains("device"))
        {
            yield return "device-histograms";
            yield return "device-distance";
        }
        if (Parts.Contains("render"))
        {
            foreach (var (name, _) in Scenes)
            {
                foreach (var oracle in new[] { "gate-level", "gate-level-aware", "lookup" })
                {
                    yield return $"render-{name}-{oracle}";
                    yield return $"int-per-ray-{name}-{oracle}";
                }
            }
        }
    }
}
