namespace QuantumRayTracing.Rendering;

/// <summary>The memory a render may use when no limit is given: what the machine has available now.</summary>
public static class AvailableMemory
{
    /// <summary>Linux's MemAvailable (free memory plus what the kernel can reclaim), elsewhere the runtime's view of the machine's memory.</summary>
    public static long Bytes()
    {
        const string meminfo = "/proc/meminfo";
        if (File.Exists(meminfo))
        {
            foreach (var line in File.ReadLines(meminfo))
            {
                if (!line.StartsWith("MemAvailable:", StringComparison.Ordinal)) continue;
                var kilobytes = line["MemAvailable:".Length..].Trim().Split(' ')[0];
                if (long.TryParse(kilobytes, out var kb)) return kb * 1024;
            }
        }
        return GC.GetGCMemoryInfo().TotalAvailableMemoryBytes;
    }
}
