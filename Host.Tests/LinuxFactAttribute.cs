namespace QuantumRayTracing.Tests;

/// <summary>
/// A fact whose files exist only on Linux (/proc, /sys); elsewhere it is reported as skipped, with the reason,
/// rather than passing without checking anything.
/// </summary>
public sealed class LinuxFactAttribute : FactAttribute
{
    public LinuxFactAttribute(string needs)
    {
        if (!OperatingSystem.IsLinux()) Skip = $"needs Linux: {needs}";
    }
}
