using System.CommandLine;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Cli;

/// <summary>
/// The options several commands share, each declared once: name, type, default and range rule live here, the
/// description (and a default) where it differs is the caller's. Options of the same name but another kind have
/// names that say which (<see cref="ImageSize"/> against <see cref="SquareSize"/>).
/// </summary>
public static class CommonOptions
{
    /// <summary>The side an image option accepts (the paper's largest renders are 128).</summary>
    public const int MaxSquareSide = 1024;

    /// <summary>The most area samples or VPLs per point an option accepts.</summary>
    public const int MaxSamples = 4096;

    /// <summary>Attaches options in the order help lists them.</summary>
    public static void AddOptions(this Command command, params IEnumerable<Option> options)
    {
        foreach (var option in options) command.Options.Add(option);
    }

    /// <summary>The scene file argument; left out, the built-in Qornell box.</summary>
    public static Argument<FileInfo?> SceneFile() => new("scene")
    {
        Description = $"Scene file (see docs/scenes.md), or a model file (.obj, .gltf, .glb) framed on a floor with a camera and a light. Default: the Qornell box with {DefaultScene.QornellPrimitives} primitives, built in.",
        Arity = ArgumentArity.ZeroOrOne,
    };

    public static Option<ulong> Seed(string description) => new("--seed") { Description = description, DefaultValueFactory = _ => 1UL };

    public static Option<int> Workers(string description) =>
        new Option<int>("--workers") { Description = description, DefaultValueFactory = _ => BridgePool.DefaultWorkers }.AtLeast(1);

    /// <summary>A cluster file (docs/cluster.md): where Q# work runs instead of local bridges, or, <paramref name="required"/>, the cluster a command serves or measures.</summary>
    public static Option<FileInfo?> Cluster(string description, bool required = false) =>
        new("--cluster") { Description = description, HelpName = "file", Required = required };

    /// <summary>The cluster file of the commands that run Q# engines on local bridges unless told otherwise.</summary>
    public static Option<FileInfo?> LocalBridgesOrCluster() =>
        Cluster("Run the Q# engines' chunks on the workers of this cluster file (docs/cluster.md) instead of local bridges. Default: none, local bridges.");

    /// <summary>A report or table written as a file, replaced only if this program wrote it.</summary>
    public static Option<FileInfo?> ReportOutput(string description) => new("--output", "-o") { Description = description };

    /// <summary>The PNG a command writes; the path is kept as given, for the default name and the JSON record.</summary>
    public static Option<string?> ImageOutput(string description) => new("--output", "-o") { Description = description };

    /// <summary>The directory named scenes are read from (<c>&lt;name&gt;.json</c>).</summary>
    public static Option<DirectoryInfo> SceneDirectory() =>
        new("--scenes") { Description = "Directory holding the scene files.", DefaultValueFactory = _ => new DirectoryInfo("Scenes") };

    /// <summary>A memory limit written 512M or 4G (<see cref="OptionText.ParseBytes"/>); left out, what the machine has available.</summary>
    public static Option<string?> MaxMemory(string description) => new Option<string?>("--max-memory") { Description = description, HelpName = "SIZE" }
        .Must(text => OptionText.ParseBytes(text).Error is { } error ? $"--max-memory: {error}" : null);

    /// <summary>An image size written WIDTHxHEIGHT or as one number for a square (<see cref="OptionText.ParseSize"/>); left out, the scene's.</summary>
    public static Option<string?> ImageSize(string description) => new Option<string?>("--size") { Description = description, HelpName = "WxH" }
        .Must(text => OptionText.ParseSize(text).Error is { } error ? $"--size: {error}" : null);

    /// <summary>The image size camera rays are cast for (`estimate`, `export search`).</summary>
    public static Option<string?> RaySize() => ImageSize("Image size the camera rays are cast for, WIDTHxHEIGHT or one number. Default: the scene's.");

    /// <summary>The camera ray through one pixel, written X,Y (<see cref="OptionText.ParsePixel"/>); <paramref name="fallback"/> says what is used without it.</summary>
    public static Option<string?> Pixel(string fallback, bool required = false) =>
        new Option<string?>("--pixel") { Description = $"The camera ray through pixel X,Y (0,0 is the top left) of the image. Default: {fallback}.", HelpName = "X,Y", Required = required }
            .Must(text => OptionText.ParsePixel(text).Error is { } error ? $"--pixel: {error}" : null);

    /// <summary>Grover iterations r, 0..<paramref name="max"/>; left out, the command's own count.</summary>
    public static Option<int?> Iterations(string description, int max) =>
        new Option<int?>("--iterations", "-r") { Description = description }.Must(r => r is < 0 || r > max ? $"--iterations must be between 0 and {max}" : null);

    /// <summary>QSS counter qubits, 1..<paramref name="max"/>: `estimate` prices them, `supersample` runs them, `export qss` writes them.</summary>
    public static Option<int?> CounterBits(string description, int max, int? fallback = null, bool shortName = true, string? helpName = null)
    {
        Option<int?> option = shortName ? new("--counter-bits", "-t") : new("--counter-bits");
        (option.Description, option.HelpName) = (description, helpName);
        if (fallback is { } given) option.DefaultValueFactory = _ => given;
        return option.Between(1, max);
    }

    /// <summary>The side of a square image, 1..<see cref="MaxSquareSide"/>.</summary>
    public static Option<int> SquareSize(string description, int fallback, string name = "--size") =>
        new Option<int>(name) { Description = description, DefaultValueFactory = _ => fallback }.Between(1, MaxSquareSide);

    /// <summary>`--area-samples`: shadow rays per surface point and area light, `render`'s default unless given.</summary>
    public static Option<int> AreaSamples(string description) =>
        new Option<int>("--area-samples") { Description = description, DefaultValueFactory = _ => RenderDefaults.AreaSamples }.Between(1, MaxSamples);

    /// <summary>`--vpl`: virtual point lights per surface point (0: no indirect light), `render`'s default unless given.</summary>
    public static Option<int> Vpl(string description) =>
        new Option<int>("--vpl") { Description = description, DefaultValueFactory = _ => RenderDefaults.Vpl }.Between(0, MaxSamples);

    /// <summary>`--max-qubits`: the widest circuit an engine may simulate; left out, each engine's own limit.</summary>
    public static Option<int?> MaxQubits(string description) =>
        new Option<int?>("--max-qubits") { Description = description, HelpName = "qubits" }.Between(1, 100_000);

    /// <summary>The value of <paramref name="option"/> when the command line gives it; null when it takes its default.</summary>
    public static T? Given<T>(ParseResult parse, Option<T> option) where T : struct =>
        parse.GetResult(option) is { Implicit: false } ? parse.GetValue(option) : null;

    /// <summary>Several values, space-separated, each <paramref name="min"/>..<paramref name="max"/>.</summary>
    public static Option<int[]> List(string name, string description, int[] fallback, string each, int min, int max, string why = "") =>
        new Option<int[]>(name) { Description = description, DefaultValueFactory = _ => fallback, AllowMultipleArgumentsPerToken = true }
            .Must(values => (values ?? []).Any(n => n < min || n > max) ? $"{name}: each {each} must be between {min} and {max}{why}" : null);

    /// <summary>`--engines`: engines out of <paramref name="allowed"/>, space- or comma-separated, each named once.</summary>
    public static Option<EngineKind[]> Engines(string description, EngineKind[] fallback, EngineKind[] allowed) =>
        new("--engines")
        {
            Description = description,
            DefaultValueFactory = _ => fallback,
            AllowMultipleArgumentsPerToken = true,
            HelpName = string.Join("|", allowed.Select(EngineFactory.Name)),
            CustomParser = r => OptionText.ParseEngines(r, "--engines", allowed),
        };

    /// <summary>A pixel's subpixel values, space-separated: 1 to 64 values, each in [0, 1].</summary>
    public static Option<double[]> CoinValues(string description, bool required = false)
        => new Option<double[]>("--values") { Description = description, AllowMultipleArgumentsPerToken = true, HelpName = "F", Required = required }
            .Must(values => (values ?? []) switch
            {
                { Length: 0 or > 64 } given => $"--values takes 1 to 64 values, got {given.Length}",
                var given => given.Where(v => v is not (>= 0 and <= 1)).Take(1).Select(bad => $"--values: {bad} is outside [0, 1]").FirstOrDefault(),
            });

    /// <summary>Square image sides, space-separated.</summary>
    public static Option<int[]> SquareSizes(string description, int[] fallback, int max = MaxSquareSide) => List("--sizes", description, fallback, "size", 1, max);

    /// <summary>Seeds 1..n: how many random cases per configuration.</summary>
    public static Option<int> SeedCount(string description, int fallback, int max, string name = "--seeds") =>
        new Option<int>(name) { Description = description, DefaultValueFactory = _ => fallback }.Between(1, max);

    public static Option<int> Trials(string description, int fallback, int max) =>
        new Option<int>("--trials") { Description = description, DefaultValueFactory = _ => fallback }.Between(10, max);

    /// <summary>Area samples and VPLs per point of the converged classical reference.</summary>
    public static Option<int> ReferenceSamples(string description, int min) =>
        new Option<int>("--reference-samples") { Description = description, DefaultValueFactory = _ => RenderDefaults.ReferenceSamples }.Between(min, MaxSamples);

    /// <summary>The largest probability that a frame fails, shared by its Grover runs (<see cref="FrameBudget"/>).</summary>
    public static Option<double> ErrorBudget(string description) =>
        new Option<double>("--error-budget") { Description = description, DefaultValueFactory = _ => FrameBudget.DefaultFrame }
            .Must(budget => FrameBudget.Problem(budget) is { } problem ? $"--error-budget {problem}" : null);

    public static Option<int> Qpus(string description, int fallback) =>
        new Option<int>("--qpus") { Description = description, DefaultValueFactory = _ => fallback }.Between(1, 1_000_000);

    /// <summary>The gate rates of a device noise model (<see cref="DeviceNoiseModel"/>): <c>1q=P,2q=P</c>.</summary>
    public static Option<string?> DeviceNoise() => DeviceModelPart("--device-noise", "1q=P,2q=P", text => DeviceNoiseModel.Parse(text, null, out var error) is null ? error : null,
        "Device noise model instead of --noise: depolarizing rate 1q after each one-qubit gate and 2q on each qubit after each gate on two or more qubits, no noise at the measurement itself (see --readout-error), e.g. 1q=1e-3,2q=5e-2; a key left out is 0."
        + " render and search: the analytic engine's searches, on the oracle --noise-oracle names; supersample: the QCoin paper's device circuits (single-qubit coins rotated to the mean the host computes, and QSS on them). Default: none.");

    /// <summary>The readout error of a device noise model: <c>P</c> or <c>P0,P1</c>.</summary>
    public static Option<string?> ReadoutError() => DeviceModelPart("--readout-error", "P|P0,P1", text => DeviceNoiseModel.Parse(null, text, out var error) is null ? error : null,
        "Readout error of the device noise model, applied to each measured bit (a search's index, a coin's heads, a QSS readout) with the seeded generator: P for both flips, or P0,P1 with P0 = P(read 1 | 0) and P1 = P(read 0 | 1). Default: none.");

    // One part of the device model's text, validated where it is parsed: the problem (a full line naming the option) or null.
    private static Option<string?> DeviceModelPart(string name, string helpName, Func<string, string?> problem, string description) =>
        new Option<string?>(name) { Description = description, HelpName = helpName }.Must(text => text is null ? null : problem(text));

    /// <summary>The device model the two options ask for (validated at parse time), or null when neither is given.</summary>
    public static DeviceNoiseModel? GetDeviceNoise(ParseResult parse, Option<string?> gates, Option<string?> readout)
    {
        var (g, r) = (parse.GetValue(gates), parse.GetValue(readout));
        if (g is null && r is null) return null;
        return DeviceNoiseModel.Parse(g, r, out var problem) ?? throw new Output.UserError(problem!);
    }
}
