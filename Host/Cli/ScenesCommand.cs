using System.CommandLine;
using QuantumRayTracing.Output;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Cli;

/// <summary>`scenes`: regenerate the scene files in Scenes/ and check any scene file.</summary>
public sealed class ScenesCommand : Command
{
    public const string GenerateCommandLine = "qrt scenes generate";

    public ScenesCommand() : base("scenes", "Generate the standard scenes, or check scene files.")
    {
        Subcommands.Add(new GenerateCommand());
        Subcommands.Add(new CheckCommand());
    }

    /// <summary>Every generated scene: file name and builder.</summary>
    public static IEnumerable<(string File, SceneBuilder Scene)> Standard() =>
        QornellBox.Sizes.Select(n => ($"qornell-{n}.json", QornellBox.Build(n)))
            .Concat(DepthComplexityScene.Sizes.Select(n => ($"depth-complexity-{n}.json", DepthComplexityScene.Build(n))))
            .Concat(QornellBox.AreaLitSizes.Select(n => ($"qornell-{n}-area.json", QornellBox.BuildAreaLit(n))))
            .Append(($"temple-{TempleScene.Primitives}.json", TempleScene.Build()));

    private sealed class GenerateCommand : Command
    {
        private readonly Option<DirectoryInfo> _directory = new("--directory", "-d")
        {
            Description = "Where to write the scene files. Files there that this command did not write are never replaced.",
            DefaultValueFactory = _ => new DirectoryInfo("Scenes"),
        };

        public GenerateCommand() : base("generate", "Write the Qornell box (8..512 primitives), Depth Complexity (32, 64), area-lit Qornell box (64) and temple (32) scene files.")
        {
            Options.Add(_directory);
            SetAction(parse =>
            {
                var directory = parse.GetValue(_directory)!.FullName;
                var files = Standard().Select(s => (Path: Path.Combine(directory, s.File), s.Scene)).ToArray();
                var marker = GeneratedReport.JsonMarker(GenerateCommandLine);
                foreach (var (path, _) in files) new GeneratedReport(path, marker).EnsureWritable();
                foreach (var (path, scene) in files)
                {
                    var report = new GeneratedReport(path, marker);
                    var text = scene.ToJson();
                    SceneLoader.Parse(report.Compose(text), path); // a generator bug must not reach disk
                    report.Write(text);
                    Console.WriteLine($"wrote {Path.GetRelativePath(Environment.CurrentDirectory, path)} ({scene.Count} primitives)");
                }
                return 0;
            });
        }
    }

    private sealed class CheckCommand : Command
    {
        private readonly Argument<FileInfo[]> _files = new("files")
        {
            Description = "Scene files to validate.",
            Arity = ArgumentArity.OneOrMore,
        };

        public CheckCommand() : base("check", "Validate scene files and print what each holds; the first problem of each is reported with file, element and reason.")
        {
            Arguments.Add(_files);
            SetAction(parse =>
            {
                var failures = 0;
                foreach (var file in parse.GetValue(_files)!)
                {
                    try
                    {
                        var scene = SceneLoader.Load(file.FullName);
                        var index = SearchRegisters.For(scene.Rectangles.Count).IndexQubits;
                        Console.WriteLine($"{file}: ok: '{scene.Name}', {scene.Rectangles.Count} rectangles ({index} index qubits), {scene.Lights.Count} point, {scene.AreaLights.Count} area and {scene.DirectionalLights.Count} directional lights, {scene.Width}x{scene.Height}, {scene.Grid}");
                    }
                    catch (SceneError e)
                    {
                        Console.Error.WriteLine($"error: {e.Message}");
                        failures++;
                    }
                }
                return failures == 0 ? 0 : 2;
            });
        }
    }
}
