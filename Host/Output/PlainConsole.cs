using Spectre.Console;

namespace QuantumRayTracing.Output;

/// <summary>
/// Output for scripts: when standard output is not a terminal, Spectre.Console writes no escape codes (whatever
/// TERM says) and wraps nothing, so a redirected line is the line a terminal would show unbroken.
/// </summary>
public static class PlainConsole
{
    /// <summary>Wide enough that no printed line or table is wrapped.</summary>
    public const int Width = 10_000;

    private static readonly Lock Gate = new();
    private static bool _configured;

    /// <summary>
    /// Makes Spectre.Console plain when standard output is redirected; once per process, keeping the writer it
    /// finds first, as Spectre.Console itself does.
    /// </summary>
    public static void ConfigureWhenRedirected()
    {
        lock (Gate)
        {
            if (_configured || !Console.IsOutputRedirected) return;
            _configured = true;
        }
        var console = AnsiConsole.Create(new AnsiConsoleSettings
        {
            Ansi = AnsiSupport.No,
            ColorSystem = ColorSystemSupport.NoColors,
            Interactive = InteractionSupport.No,
            Out = new AnsiConsoleOutput(Console.Out),
        });
        console.Profile.Width = Width;
        AnsiConsole.Console = console;
    }
}
