using System.CommandLine;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Cli;

/// <summary>`bench accuracy`: options → <see cref="AccuracySettings"/> → <see cref="AccuracyExperiment"/> (docs/accuracy.md).</summary>
public sealed class BenchAccuracyCommand : Command
{
    public const string CommandLine = "qrt bench accuracy";

    private readonly Option<int[]> _sizes = new("--sizes")
    {
        Description = "Square image sizes (space-separated).",
        DefaultValueFactory = _ => [4, 8, 16, 32, 64, 128],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<int> _seeds = new("--seeds")
    {
        Description = "Random scenes per kind and size (seeds 1..n).",
        DefaultValueFactory = _ => 10,
    };

    private readonly Option<int> _deepSize = new("--deep-size")
    {
        Description = "Largest size rendered for the 4,000-rectangle scenes (their rays each test 4,000 primitives classically).",
        DefaultValueFactory = _ => 64,
    };

    private readonly BenchReportOptions _report = new(CommandLine, "docs/accuracy.md");

    public BenchAccuracyCommand() : base("accuracy", "Wrong pixels and Int/Ray of the default pipeline on random scenes by size, beside --lattice 0 and the paper's plain pipeline (analytic engine).")
    {
        Options.Add(_sizes);
        Options.Add(_seeds);
        Options.Add(_deepSize);
        _report.AddTo(this, scenes: false, seed: false, workers: false);
        _seeds.Between(1, 1000);
        _deepSize.Between(1, 1024);
        _sizes.Validators.Add(r =>
        {
            if (r.GetValueOrDefault<int[]>() is { } sizes && sizes.Any(s => s is < 1 or > 1024)) r.AddError("--sizes: each size must be 1..1024");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var settings = new AccuracySettings(parse.GetValue(_sizes)!, parse.GetValue(_seeds), parse.GetValue(_deepSize), DefaultScene.Load(null));
        var report = AccuracyExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, BenchReportOptions.Footer(MachineDescription.Describe(null, null)));
        return 0;
    }
}
