using System.CommandLine;
using System.Globalization;
using System.Text;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;
using QuantumRayTracing.Randomness;
using Spectre.Console;

namespace QuantumRayTracing.Cli;

/// <summary>`bench`: measured speed tables, written as Markdown for docs/.</summary>
public sealed class BenchCommand : Command
{
    public BenchCommand() : base("bench", "Measure speed and write the tables in docs/.")
    {
        Subcommands.Add(new GroverBenchCommand());
        Subcommands.Add(new BenchRenderCommand());
        Subcommands.Add(new BenchOptimisedCommand());
        Subcommands.Add(new BenchParetoCommand());
        Subcommands.Add(new BenchLightsCommand());
        Subcommands.Add(new BenchSupersampleCommand());
        Subcommands.Add(new BenchSupersampleImagesCommand());
        Subcommands.Add(new BenchCapacityCommand());
        Subcommands.Add(new BenchSoakCommand());
        Subcommands.Add(new BenchAccuracyCommand());
        Subcommands.Add(new BenchNoiseCommand());
        Subcommands.Add(new BenchFullStateCommand());
        Subcommands.Add(new BenchClusterCommand());
    }

    private sealed class GroverBenchCommand : Command
    {
        private readonly Option<int[]> _sizes = new("--sizes")
        {
            Description = "Search sizes N (space-separated).",
            DefaultValueFactory = _ => [8, 64, 512],
            AllowMultipleArgumentsPerToken = true,
        };

        private readonly Option<int[]> _batches = new("--batches")
        {
            Description = "Requests per engine call (space-separated).",
            DefaultValueFactory = _ => [1, 100, 1000],
            AllowMultipleArgumentsPerToken = true,
        };

        private readonly Option<int> _workers = new("--workers")
        {
            Description = "Bridges for the all-workers column. Default: the core count.",
            DefaultValueFactory = _ => BridgePool.DefaultWorkers,
        };

        private readonly Option<ulong> _seed = new("--seed")
        {
            Description = "Seed of the marked indices and the analytic engine.",
            DefaultValueFactory = _ => 1UL,
        };

        private readonly Option<FileInfo?> _output = new("--output", "-o")
        {
            Description = "Write the Markdown report here (e.g. docs/performance.md). It replaces only a report this command wrote before. Default: the report is printed only.",
        };

        public GroverBenchCommand() : base("grover", "Cost per Grover run: fullstate (1 worker and all workers) and analytic, for each N and batch size.")
        {
            Options.Add(_sizes);
            Options.Add(_batches);
            Options.Add(_workers);
            Options.Add(_seed);
            Options.Add(_output);
            _sizes.Validators.Add(r =>
            {
                if ((r.GetValueOrDefault<int[]>() ?? []).Any(n => n is < 1 or > 4096)) r.AddError("--sizes: each N must be between 1 and 4096");
            });
            _batches.Validators.Add(r =>
            {
                if ((r.GetValueOrDefault<int[]>() ?? []).Any(b => b < 1)) r.AddError("--batches: each batch size must be at least 1");
            });
            _workers.AtLeast(1);
            SetAction(Execute);
        }

        private int Execute(ParseResult parse)
        {
            var output = parse.GetValue(_output);
            var report = new GeneratedReport(output?.FullName, GeneratedReport.MarkdownMarker("qrt bench grover"));
            report.EnsureWritable();

            var random = new SeededRandom(parse.GetValue(_seed));
            var workers = parse.GetValue(_workers);
            var rows = new List<GroverBenchmark.Row>();
            string machine;
            using (var single = new FullStateEngine(new BridgePool(1)))
            using (var parallel = new FullStateEngine(new BridgePool(workers)))
            {
                var versions = single.Pool.Bridges[0].Version();
                machine = MachineDescription.Describe(versions["qsharp"]?.GetValue<string>(), versions["node"]?.GetValue<string>());
                var analytic = new AnalyticEngine(random.Fork(RandomStreams.Engine));
                var cases = parse.GetValue(_sizes)!.SelectMany(n => parse.GetValue(_batches)!.Select(b => (Count: n, Batch: b))).ToArray();
                AnsiConsole.Progress().Start(progress =>
                {
                    var task = progress.AddTask("benchmarking Grover runs", maxValue: cases.Length);
                    foreach (var (count, batch) in cases)
                    {
                        var requests = GroverBenchmark.Requests(count, batch, random);
                        var repeats = GroverBenchmark.Repeats(batch);
                        var oneWorker = GroverBenchmark.MillisecondsPerRun(single, requests, repeats);
                        var allWorkers = GroverBenchmark.MillisecondsPerRun(parallel, requests, repeats);
                        var analyticRequests = Enumerable.Range(0, Math.Max(1, 100_000 / batch)).SelectMany(_ => requests).ToArray();
                        var analyticMicros = 1000 * GroverBenchmark.MillisecondsPerRun(analytic, analyticRequests, 5);
                        rows.Add(new(count, GroverBenchmark.OptimalIterations(count), batch, oneWorker, allWorkers, analyticMicros));
                        task.Increment(1);
                    }
                });
            }

            var text = Markdown(rows, workers, machine, string.Join(' ', Environment.GetCommandLineArgs().Skip(1)));
            Console.WriteLine(text);
            report.Write(text);
            return 0;
        }

        private static string Markdown(List<GroverBenchmark.Row> rows, int workers, string machine, string arguments)
        {
            static string F(double v) => v.ToString(v >= 100 ? "0" : v >= 10 ? "0.0" : "0.000", CultureInfo.InvariantCulture);
            var text = new StringBuilder();
            text.AppendLine("# Performance: Grover runs per engine");
            text.AppendLine();
            text.AppendLine("Wall time per Grover run (prepare the uniform superposition over N indices, r = floor(π/4·sqrt N) iterations with one marked index, measure)");
            text.AppendLine("on each engine, for batches of 1, 100 and 1000 requests per engine call. The batch of 1 shows the fixed cost of one call through the");
            text.AppendLine("Node bridge (the QDK compiles the program on every call); large batches show the amortised cost of the simulation itself.");
            text.AppendLine("`fullstate` is the Q# operation `MeasureGroverBatch` on the QDK full-state simulator; `analytic` samples the exact outcome");
            text.AppendLine("distribution in C#. Each figure is the median of 9 (batch 1), 3 (batch 100) or 1 (batch 1000) timed calls after a warm-up call.");
            text.AppendLine();
            text.AppendLine("| N | r | batch | fullstate, 1 worker: ms/run | fullstate, " + workers + " workers: ms/run | fullstate, 1 worker: ms/call | analytic: µs/run | fullstate / analytic |");
            text.AppendLine("|---|---|---|---|---|---|---|---|");
            foreach (var r in rows)
                text.AppendLine($"| {r.Count} | {r.Iterations} | {r.Batch} | {F(r.FullStateOneWorkerMs)} | {F(r.FullStateAllWorkersMs)} | {F(r.FullStateOneWorkerMs * r.Batch)} | {F(r.AnalyticMicroseconds)} | {F(r.FullStateOneWorkerMs * 1000 / r.AnalyticMicroseconds)}x |");
            text.AppendLine();
            text.AppendLine("Whole renders on the fullstate engine, with their calls, simulation and simulator-only floor: [performance-fullstate.md](performance-fullstate.md) (`qrt bench fullstate`).");
            text.AppendLine();
            text.AppendLine($"Machine: {machine}.");
            text.AppendLine($"Command: `dotnet run --project Host -c Release -- {arguments}`.");
            return text.ToString();
        }
    }
}
