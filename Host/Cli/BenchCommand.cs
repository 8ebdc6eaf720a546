using System.CommandLine;

namespace QuantumRayTracing.Cli;

/// <summary>`bench`: measured speed tables, written as Markdown for docs/.</summary>
public sealed class BenchCommand : Command
{
    public BenchCommand() : base("bench", "Measure speed and write the tables in docs/.")
    {
        Subcommands.Add(new BenchGroverCommand());
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
        Subcommands.Add(new BenchNoiseEstimationCommand());
        Subcommands.Add(new BenchFullStateCommand());
        Subcommands.Add(new BenchClusterCommand());
    }
}
