using System.Runtime.InteropServices;

namespace QuantumRayTracing.Reports;

/// <summary>One line saying what a benchmark ran on, for the tables it writes.</summary>
public static class MachineDescription
{
    public static string Describe(string? qsharpVersion, string? nodeVersion)
    {
        var cpu = "unknown CPU";
        try
        {
            cpu = File.ReadLines("/proc/cpuinfo").FirstOrDefault(l => l.StartsWith("model name"))?.Split(':', 2)[1].Trim() ?? cpu;
        }
        catch (IOException) { }
        catch (UnauthorizedAccessException) { }
        return $"{cpu}, {Environment.ProcessorCount} cores, {RuntimeInformation.OSDescription}, {RuntimeInformation.FrameworkDescription}" +
               (nodeVersion is null ? "" : $", Node {nodeVersion}") + (qsharpVersion is null ? "" : $", qsharp-lang {qsharpVersion}");
    }
}
