using System.CommandLine;
using QuantumRayTracing.Export;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Cli;

/// <summary>`export pooled-search`: one pooled search over several camera rays' (ray, primitive) pairs with the gate-level oracle.</summary>
public sealed class ExportPooledSearchCommand : Command
{
    private readonly Argument<FileInfo?> _scene = CommonOptions.SceneFile();

    private readonly Option<string[]> _pixels = new Option<string[]>("--pixels")
    {
        Description = "The pool: the camera rays through these pixels, X,Y each, space-separated (at least one). Default: none, it is required.",
        Required = true,
        AllowMultipleArgumentsPerToken = true,
        HelpName = "X,Y...",
    };

    private readonly Option<string?> _size = CommonOptions.RaySize();

    private readonly Option<int?> _iterations = CommonOptions.Iterations("Grover iterations r (0 to 64). Default: the optimal count for the pool's marked pairs among its rays x N pairs.", 64);

    private readonly Option<string> _oracle = ExportOutputOptions.Oracle();

    private readonly ExportOutputOptions _output = new();

    public ExportPooledSearchCommand() : base("pooled-search", "One pooled search, as a budget round runs it: the uniform superposition over several rays' (ray, primitive) pairs, r pooled Grover iterations, the pair register measured.")
    {
        Arguments.Add(_scene);
        this.AddOptions(_pixels, _size, _iterations, _oracle);
        _pixels.Validators.Add(r =>
        {
            var texts = r.GetValueOrDefault<string[]>() ?? [];
            if (texts.Length == 0) r.AddError("--pixels: name at least one pixel");
            foreach (var text in texts)
                if (OptionText.ParsePixel(text).Error is { } error) r.AddError($"--pixels: {error}");
        });
        _output.AddTo(this, parse =>
        {
            var scene = DefaultScene.Load(parse.GetValue(_scene));
            var (width, height) = OptionText.SizeOr(parse.GetValue(_size), scene);
            var pixels = parse.GetValue(_pixels)!.Select(text => OptionText.PixelIn(text, width, height, "--pixels")).ToArray();
            return PooledSearchExport.ForPixels(scene, width, height, pixels, ExportOutputOptions.Construction(parse, _oracle), parse.GetValue(_iterations));
        });
    }
}
