using System.CommandLine;
using QuantumRayTracing.Export;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Cli;

/// <summary>`export search`: one camera ray's Grover search with the gate-level oracle.</summary>
public sealed class ExportSearchCommand : Command
{
    private readonly Argument<FileInfo?> _scene = CommonOptions.SceneFile();

    private readonly Option<string> _pixel = new("--pixel")
    {
        Description = "The camera ray through pixel X,Y (0,0 is the top left) of the image. Default: none, it is required.",
        HelpName = "X,Y",
        Required = true,
    };

    private readonly Option<string?> _size = CommonOptions.ImageSize("Image size the camera rays are cast for, WIDTHxHEIGHT or one number. Default: the scene's.");

    private readonly Option<int?> _iterations = new("--iterations", "-r")
    {
        Description = "Grover iterations r (0 to 64). Default: the optimal count for the ray's marked set, floor(pi / (4 asin sqrt(M/N))).",
    };

    private readonly Option<string> _oracle = new("--oracle")
    {
        Description = "How the oracle is built. Only narrow (unload by lookup) exports: the QDK cannot compile the measured unlookup of compact and baseline to QIR.",
        DefaultValueFactory = _ => OracleConstruction.Narrow.Name,
        HelpName = string.Join('|', OracleConstruction.Named.Select(c => c.Name)),
    };

    private readonly ExportOutputOptions _output = new();

    public ExportSearchCommand() : base("search", "One ray's Grover search: the uniform superposition over the primitives, r iterations of the gate-level oracle and the diffusion, the index register measured.")
    {
        Arguments.Add(_scene);
        this.AddOptions(_pixel, _size, _iterations, _oracle);
        _output.AddTo(this);
        _pixel.Validators.Add(r =>
        {
            if (OptionText.ParsePixel(r.GetValueOrDefault<string>()) is { Error: { } error }) r.AddError($"--pixel: {error}");
        });
        _iterations.Validators.Add(r =>
        {
            if (r.GetValueOrDefault<int?>() is < 0 or > 64) r.AddError("--iterations must be between 0 and 64");
        });
        _oracle.Validators.Add(r =>
        {
            var name = r.GetValueOrDefault<string>();
            var construction = OracleConstruction.Named.FirstOrDefault(c => c.Name == name);
            if (construction is null) r.AddError($"--oracle: unknown construction '{name}'; expected {string.Join(", ", OracleConstruction.Named.Select(c => c.Name))}");
            else if (!SearchExport.CanExport(construction)) r.AddError($"--oracle {name}: its measured unlookup does not compile to QIR on the QDK; export narrow");
        });
        SetAction(parse =>
        {
            var scene = DefaultScene.Load(parse.GetValue(_scene));
            var (width, height) = OptionText.SizeOr(parse.GetValue(_size), scene);
            var pixel = OptionText.ParsePixel(parse.GetValue(_pixel)).Pixel!.Value;
            if (pixel.X >= width || pixel.Y >= height) throw new UserError($"--pixel {pixel.X},{pixel.Y} is outside the {width}x{height} image");
            if (scene.Rectangles.Count < 2) throw new UserError($"scene {scene.Name}: a search needs at least 2 primitives");
            var construction = OracleConstruction.Named.Single(c => c.Name == parse.GetValue(_oracle));
            var subject = SearchExport.ForPixel(scene, width, height, pixel.X, pixel.Y, construction, parse.GetValue(_iterations));
            ExportRun.Run(_output.Settings(parse, subject), Console.Out);
            return ExitCodes.Success;
        });
    }
}
