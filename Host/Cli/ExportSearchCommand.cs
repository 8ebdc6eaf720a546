using System.CommandLine;
using QuantumRayTracing.Export;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Cli;

/// <summary>`export search`: one camera ray's Grover search with the gate-level oracle.</summary>
public sealed class ExportSearchCommand : Command
{
    private readonly Argument<FileInfo?> _scene = CommonOptions.SceneFile();

    private readonly Option<string?> _pixel = CommonOptions.Pixel("none, it is required", required: true);

    private readonly Option<string?> _size = CommonOptions.RaySize();

    private readonly Option<int?> _iterations = CommonOptions.Iterations("Grover iterations r (0 to 64). Default: the optimal count for the ray's marked set, floor(pi / (4 asin sqrt(M/N))).", 64);

    private readonly Option<string> _oracle = ExportOutputOptions.Oracle();

    private readonly ExportOutputOptions _output = new();

    public ExportSearchCommand() : base("search", "One ray's Grover search: the uniform superposition over the primitives, r iterations of the gate-level oracle and the diffusion, the index register measured.")
    {
        Arguments.Add(_scene);
        this.AddOptions(_pixel, _size, _iterations, _oracle);
        _output.AddTo(this, parse =>
        {
            var scene = DefaultScene.Load(parse.GetValue(_scene));
            var (width, height) = OptionText.SizeOr(parse.GetValue(_size), scene);
            var (x, y) = OptionText.PixelIn(parse.GetValue(_pixel)!, width, height);
            return SearchExport.ForPixel(scene, width, height, x, y, ExportOutputOptions.Construction(parse, _oracle), parse.GetValue(_iterations));
        });
    }
}
