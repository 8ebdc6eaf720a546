using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Reports;

/// <summary>The lines closing every generated report: the machine, where the Q# work ran, and the command that regenerates it.</summary>
public static class ReportFooter
{
    public static IReadOnlyList<string> Lines(string machine, BridgePool? cluster = null) =>
    [
        $"Machine: {machine}{(cluster is null ? "" : $"; Q# engines on {cluster.Where}")}.",
        $"Command: `dotnet run --project Host -c Release -- {string.Join(' ', Environment.GetCommandLineArgs().Skip(1))}`.",
    ];
}
