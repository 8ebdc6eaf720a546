using System.CommandLine;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `estimate sweep`: the oracle's resource estimates against the number of primitives and the
/// coordinate bits, before and after the smaller construction, written as Markdown (docs/estimates.md).
/// </summary>
public sealed class EstimateSweepCommand : Command
{
    public const string CommandLine = "qrt estimate sweep";

    private readonly Option<int[]> _primitives = new("--primitives")
    {
        Description = $"Primitive counts N of the sweep over N, on a {EstimateSweep.DefaultCoordinateBits}-bit grid (space-separated).",
        DefaultValueFactory = _ => EstimateSweep.Primitives.ToArray(),
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<int[]> _bits = new("--bits")
    {
        Description = $"Coordinate bits of the sweep over the grid, at N = {EstimateSweep.DefaultPrimitives} (space-separated).",
        DefaultValueFactory = _ => EstimateSweep.CoordinateBits.ToArray(),
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<int[]> _ablation = new("--ablation")
    {
        Description = "Primitive counts at which each change of the construction is also measured on its own (space-separated).",
        DefaultValueFactory = _ => [4, EstimateSweep.DefaultPrimitives],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<FileInfo?> _output = new("--output", "-o")
    {
        Description = "Write the Markdown report here (e.g. docs/estimates.md). It replaces only a report this command wrote before. Default: the report is printed only.",
    };

    private readonly EstimateOptions _options = new();

    public EstimateSweepCommand() : base("sweep", "The oracle's estimates against the number of primitives (4..512) and the coordinate bits (2..8), before and after the compact construction, as Markdown.")
    {
        Options.Add(_primitives);
        Options.Add(_bits);
        Options.Add(_ablation);
        Options.Add(_output);
        _options.AddTo(this, withFormat: false);
        foreach (var option in new[] { _primitives, _ablation })
            option.Validators.Add(r =>
            {
                if (r.TryGetValue<int[]>(out var values) && (values ?? []).Any(n => n is < 1 or > 4096)) r.AddError($"{option.Name}: each N must be between 1 and 4096");
            });
        _bits.Validators.Add(r =>
        {
            if (r.TryGetValue<int[]>(out var values) && (values ?? []).Any(c => c is < 2 or > 16)) r.AddError("--bits: each count must be between 2 and 16");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var output = parse.GetValue(_output);
        var report = new GeneratedReport(output?.FullName, GeneratedReport.MarkdownMarker(CommandLine));
        report.EnsureWritable();
        var primitives = parse.GetValue(_primitives)!;
        var bits = parse.GetValue(_bits)!;
        var ablation = parse.GetValue(_ablation)!;

        var wanted = SweepReport.Wanted(primitives, bits, ablation).ToArray();
        var subjects = wanted.Select(p => (p.Primitives, p.Bits)).Distinct().ToDictionary(p => p, p => EstimateSweep.Subject(p.Primitives, p.Bits));
        var jobs = wanted.Select(p => (EstimatedCircuits.Oracle, subjects[(p.Primitives, p.Bits)].With(p.Construction))).ToArray();

        var estimator = _options.Create(parse, out var pool);
        IReadOnlyList<CircuitEstimate> estimates;
        string machine;
        using (pool)
        {
            var versions = pool.Bridges[0].Version();
            machine = MachineDescription.Describe(versions["qsharp"]?.GetValue<string>(), versions["node"]?.GetValue<string>());
            estimates = EstimateProgress.Run(estimator, jobs, $"estimating {jobs.Length} oracles");
        }

        var points = wanted.Zip(estimates).ToDictionary(p => (p.First.Primitives, p.First.Bits, p.First.Construction.Name), p => p.Second);
        var sweep = new SweepReport(points, estimator.Models);
        // Plots go beside the report as <report>-<suffix>.png; without a report file there is nowhere to put them.
        var plots = output is null ? [] : SweepPlots.Draw(sweep, primitives, bits)
            .Select(p => (p.Image, Path: Path.Combine(output.DirectoryName!, $"{Path.GetFileNameWithoutExtension(output.Name)}-{p.Suffix}.png"), p.Caption))
            .ToArray();
        ImageFiles.EnsureWritable(plots.Select(p => p.Path).ToArray(), []);
        var arguments = string.Join(' ', Environment.GetCommandLineArgs().Skip(1));
        var text = sweep.Markdown(primitives, bits, ablation, $"dotnet run --project Host -c Release -- {arguments}", machine,
            plots.Select(p => (Path.GetFileName(p.Path), p.Caption)).ToArray());
        Console.WriteLine(text);
        report.Write(text);
        ImageFiles.Write(plots.Select(p => (p.Image, p.Path)));
        return 0;
    }
}
