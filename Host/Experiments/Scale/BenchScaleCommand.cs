using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench scale`: options → <see cref="ScaleSettings"/> → <see cref="ScaleExperiment"/> (docs/scale.md).</summary>
public sealed class BenchScaleCommand : Command
{
    public const string CommandText = "qrt bench scale";

    private readonly Option<int[]> _sizes = CommonOptions.List("--sizes", "Square image sizes (space-separated); from 1024 on a render is forecast and may be refused.",
        ScaleSettings.DefaultSizes, "size", 1, Scenes.SceneLoader.MaxImageSide);

    private readonly Option<EngineKind[]> _engines = CommonOptions.Engines("Engines measured (space- or comma-separated).",
        ScaleSettings.DefaultEngines, [EngineKind.Classical, EngineKind.Bvh, EngineKind.Analytic, EngineKind.Randomized]);

    private readonly BenchReportOptions _report = new(CommandText, "docs/scale.md");

    public BenchScaleCommand() : base("scale", "Wall time and peak memory of render against the image size (128x128 to 8192x8192), per engine, each render in a process of its own (Linux).")
    {
        this.AddOptions(_sizes, _engines);
        _report.AddTo(this, seed: true, workers: false);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var scene = Path.Combine(parse.GetValue(_report.SceneDirectory)!.FullName, "qornell-64.json");
        if (!File.Exists(scene)) throw new Output.UserError($"--scenes: {scene} does not exist");
        var settings = new ScaleSettings(scene, parse.GetValue(_sizes)!, parse.GetValue(_engines)!, parse.GetValue(_report.Seed));
        var report = ScaleExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(null, null)));
        return ExitCodes.Success;
    }
}
