using System.Diagnostics;
using System.Text.Json.Nodes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// One `render` in a child process of this program: its exit code, its JSON figures, its standard output, its one-line error, its wall time and
/// its peak resident memory (Linux's VmHWM, read while it runs; the high-water mark only grows, so the last reading is
/// the peak up to the last <see cref="PollInterval"/>).
/// </summary>
public sealed record RenderProcess(int ExitCode, JsonObject? Figures, string Output, string Error, TimeSpan WallTime, long PeakBytes)
{
    public static readonly TimeSpan PollInterval = TimeSpan.FromMilliseconds(50);

    public static RenderProcess Run(IEnumerable<string> arguments, string jsonFile)
    {
        var (executable, prefix) = Self();
        var start = new ProcessStartInfo(executable) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (var a in prefix.Concat(arguments).Concat(["--json", jsonFile])) start.ArgumentList.Add(a);
        var clock = Stopwatch.StartNew();
        using var process = Process.Start(start) ?? throw new InvalidOperationException($"cannot start {executable}");
        var output = process.StandardOutput.ReadToEndAsync();
        var error = process.StandardError.ReadToEndAsync();
        long peak = 0;
        while (!process.WaitForExit(PollInterval)) peak = Math.Max(peak, HighWaterMark(process.Id));
        process.WaitForExit();
        var wall = clock.Elapsed;
        var figures = process.ExitCode == 0 && File.Exists(jsonFile) ? JsonNode.Parse(File.ReadAllText(jsonFile))?["figures"]?.AsObject() : null;
        var lastError = error.Result.Split('\n', StringSplitOptions.RemoveEmptyEntries).LastOrDefault(l => l.StartsWith("error:", StringComparison.Ordinal)) ?? "";
        return new RenderProcess(process.ExitCode, figures, output.Result, lastError, wall, peak);
    }

    // This program as a command line: the apphost, or dotnet with the assembly.
    private static (string Executable, string[] Prefix) Self()
    {
        var path = Environment.ProcessPath ?? "dotnet";
        var assembly = typeof(RenderProcess).Assembly.Location;
        return Path.GetFileNameWithoutExtension(path) == "dotnet" ? (path, [assembly]) : (path, []);
    }

    private static long HighWaterMark(int pid)
    {
        try
        {
            foreach (var line in File.ReadLines($"/proc/{pid}/status"))
                if (line.StartsWith("VmHWM:", StringComparison.Ordinal) && long.TryParse(line[6..].Trim().Split(' ')[0], out var kb)) return kb * 1024;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // The process ended between two readings.
        }
        return 0;
    }
}
