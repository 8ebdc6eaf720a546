using System.Globalization;

namespace QuantumRayTracing.Experiments;

/// <summary>How busy the machine was while a benchmark timed something: above the core count, other work shared it.</summary>
public static class MachineLoad
{
    /// <summary>The one-minute load average (Linux /proc/loadavg); null where there is none.</summary>
    public static double? OneMinute()
    {
        try
        {
            return double.TryParse(File.ReadAllText("/proc/loadavg").Split(' ')[0], NumberStyles.Float, CultureInfo.InvariantCulture, out var load) ? load : null;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return null;
        }
    }
}
