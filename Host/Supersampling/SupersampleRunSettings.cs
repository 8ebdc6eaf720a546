using QuantumRayTracing.Estimation;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Supersampling;

/// <summary>
/// Everything one run of <see cref="SupersampleRun"/> needs: what `supersample` reads from its options.
/// </summary>
/// <param name="Method">The estimator and its parameters, s among them.</param>
/// <param name="ImageFile">The image supersampled, each s x s block of its pixels one output pixel; null renders a scene instead.</param>
/// <param name="SceneFile">The scene rendered classically at s times the output size (without <paramref name="ImageFile"/>); null: the built-in Qornell box.</param>
/// <param name="Size">The output size of a scene; null: the scene's own.</param>
/// <param name="Engine">Where the coins and QSS runs are simulated (analytic or fullstate), on which bridges and under which noise: a
/// device model (<see cref="EngineSetup.Device"/>) runs the estimators on the single-qubit coins (<see cref="DirectCoinEngine"/>).</param>
/// <param name="Seed">The seed of every classical random choice (the analytic engine's outcomes).</param>
/// <param name="Output">The PNG the estimate is written to; bit-plane QSS writes its confidence map beside it.</param>
/// <param name="TableDirectory">Where QSS lookup tables are kept between runs; null: the user's cache directory.</param>
public sealed record SupersampleRunSettings(
    SupersampleSettings Method,
    string? ImageFile,
    string? SceneFile,
    (int Width, int Height)? Size,
    EngineSetup Engine,
    ulong Seed,
    string Output,
    string? TableDirectory = null)
{
    /// <summary>The fullstate engine simulates every (pixel, channel) item: above this many output pixels it is refused.</summary>
    public const int MaxFullStatePixels = 256;

    /// <summary>What is wrong with the input and noise options given together, before the method's own (<see cref="SupersampleSettings.Problem"/>); null if nothing.</summary>
    public static string? InputProblem(bool image, bool scene, bool size, bool pauliNoise, bool deviceNoise) =>
        image && scene ? "--image and --scene: give one input, not both"
        : image && size ? "--size applies to scenes only: an image's output size is its size divided by --subpixels"
        : pauliNoise && deviceNoise ? "--noise and --device-noise/--readout-error: give one noise model, not both"
        : null;

    /// <summary>The file read, if any: the image or the scene.</summary>
    public string? InputFile => ImageFile ?? SceneFile;

    /// <summary>Every PNG the run writes: the estimate, then with bit-plane QSS the confidence map.</summary>
    public IReadOnlyList<string> Files => Method.UsesLookupTable ? [Output, ImageFiles.Beside(Output, "confidence")] : [Output];
}
