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

    private readonly Option<string> _oracle = new Option<string>("--oracle")
    {
        Description = "How the oracle is built. The export clears the loaded registers by a second lookup whatever the construction (the QDK cannot compile the measured unlookup of compact, baseline and device to QIR), so compact exports as narrow.",
        DefaultValueFactory = _ => OracleConstruction.Narrow.Name,
        HelpName = string.Join('|', OracleConstruction.Named.Select(c => c.Name)),
    }.Must(name => OracleConstruction.Named.Any(c => c.Name == name)
        ? null
        : $"--oracle: unknown construction '{name}'; expected {string.Join(", ", OracleConstruction.Named.Select(c => c.Name))}");

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
            return SearchExport.ForPixel(scene, width, height, x, y, OracleConstruction.Named.Single(c => c.Name == parse.GetValue(_oracle)), parse.GetValue(_iterations));
        });
    }
}
