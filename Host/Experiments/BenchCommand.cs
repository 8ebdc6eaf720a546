using System.CommandLine;
using QuantumRayTracing.Cli;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench`: measured speed tables, written as Markdown for docs/.</summary>
public sealed class BenchCommand : Command
{
    public BenchCommand() : base("bench", "Measure speed and write the tables in docs/.")
    {
        Subcommands.Add(new BenchGroverPerformanceCommand());
        Subcommands.Add(new BenchRenderResultsCommand());
        Subcommands.Add(new BenchOptimisedTracingCommand());
        Subcommands.Add(new BenchSpeedVsErrorCommand());
        Subcommands.Add(new BenchLightsCommand());
        Subcommands.Add(new BenchLightTransportCommand());
        Subcommands.Add(new BenchSupersamplingResultsCommand());
        Subcommands.Add(new BenchSupersamplingImagesCommand());
        Subcommands.Add(new BenchSimulatorCapacityCommand());
        Subcommands.Add(new BenchSoakCommand());
        Subcommands.Add(new BenchAccuracyCommand());
        Subcommands.Add(new BenchNoiseCommand());
        Subcommands.Add(new BenchNoiseEstimationCommand());
        Subcommands.Add(new BenchDeviceNoiseCommand());
        Subcommands.Add(new BenchEstimationCommand());
        Subcommands.Add(new BenchFullStatePerformanceCommand());
        Subcommands.Add(new BenchClusterPerformanceCommand());
        Subcommands.Add(new BenchBvhComparisonCommand());
        Subcommands.Add(new BenchScaleCommand());
    }
}
