using System.CommandLine;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Cli;

/// <summary>`scenes`: regenerate the scene files in Scenes/ and check any scene file.</summary>
public sealed class ScenesCommand : Command
{
    public const string GenerateCommandText = "qrt scenes generate";

    public ScenesCommand() : base("scenes", "Generate the standard scenes, or check scene files.")
    {
        Subcommands.Add(new GenerateCommand());
        Subcommands.Add(new CheckCommand());
    }

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
                StandardScenes.Write(parse.GetValue(_directory)!.FullName, GenerateCommandText,
                    (path, primitives) => Console.WriteLine($"wrote {Path.GetRelativePath(Environment.CurrentDirectory, path)} ({primitives} primitives)"));
                return ExitCodes.Success;
            });
        }
    }

    private sealed class CheckCommand : Command
    {
        private readonly Argument<FileInfo[]> _files = new("files")
        {
            Description = "Scene files (JSON) or mesh files (.obj, .gltf, .glb) to validate.",
            Arity = ArgumentArity.OneOrMore,
        };

        public CheckCommand() : base("check", "Validate scene or mesh files and print what each holds (for a mesh: its triangles, bounds, the grid chosen and the rounding onto it); the first problem of each is reported with file, element (or line) and reason.")
        {
            Arguments.Add(_files);
            SetAction(parse => SceneCheck.Run(parse.GetValue(_files)!, Console.Out, Console.Error) == 0 ? ExitCodes.Success : ExitCodes.BadInput);
        }
    }
}
