using System.Diagnostics;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>
/// Runs the built `qrt` program as its own process, as a user would: needed where the environment
/// matters (which Node.js the bridge starts) and to see exactly what reaches the terminal.
/// </summary>
internal static class QrtProcess
{
    public static (int Code, string Output, string Error) Run(IReadOnlyDictionary<string, string> environment, string workingDirectory, params string[] args)
    {
        var start = new ProcessStartInfo("dotnet")
        {
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
            WorkingDirectory = workingDirectory,
        };
        start.ArgumentList.Add(Path.Combine(AppContext.BaseDirectory, "qrt.dll"));
        foreach (var arg in args) start.ArgumentList.Add(arg);
        foreach (var (name, value) in environment) start.Environment[name] = value;
        using var process = Process.Start(start)!;
        var output = process.StandardOutput.ReadToEndAsync();
        var error = process.StandardError.ReadToEndAsync();
        if (!process.WaitForExit(TimeSpan.FromMinutes(3)))
        {
            process.Kill(entireProcessTree: true);
            throw new TimeoutException($"qrt {string.Join(' ', args)} did not finish within 3 minutes");
        }
        return (process.ExitCode, output.Result, error.Result);
    }
}
