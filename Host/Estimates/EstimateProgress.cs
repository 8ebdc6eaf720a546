using Spectre.Console;

namespace QuantumRayTracing.Estimates;

/// <summary>Runs estimates with a progress bar on an interactive console, silently otherwise (so piped Markdown or CSV stays clean).</summary>
public static class EstimateProgress
{
    public static IReadOnlyList<CircuitEstimate> Run(ResourceEstimator estimator, IReadOnlyList<(EstimatedCircuit, EstimateSubject)> jobs, string title)
    {
        if (!AnsiConsole.Profile.Capabilities.Interactive) return estimator.Estimate(jobs);
        return AnsiConsole.Progress().AutoClear(true).Start(progress =>
        {
            var task = progress.AddTask(title, maxValue: jobs.Count);
            return estimator.Estimate(jobs, () => task.Increment(1));
        });
    }
}
