using QuantumRayTracing.Cli;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>Runs a command with its console output captured; one run at a time, since the console's writers are global.</summary>
internal static class ConsoleCapture
{
    private static readonly Lock Gate = new();

    public static (int Code, string Error) Run(params string[] args)
    {
        var (code, _, error) = RunCapturingOutput(args);
        return (code, error);
    }

    /// <summary>
    /// Standard output and error of one run. Spectre.Console keeps the writer it found first, so what a
    /// command prints through it is not captured; the commands print nothing through it before they fail on bad input.
    /// </summary>
    public static (int Code, string Output, string Error) RunCapturingOutput(params string[] args)
    {
        var code = 0;
        var (output, error) = Capture(() => code = CommandLine.Run(args));
        return (code, output, error);
    }

    /// <summary>Standard output and error of <paramref name="action"/>, which runs alone with the console captured.</summary>
    public static (string Output, string Error) Capture(Action action)
    {
        lock (Gate)
        {
            var (savedOutput, savedError) = (Console.Out, Console.Error);
            var (output, error) = (new StringWriter(), new StringWriter());
            Console.SetOut(output);
            Console.SetError(error);
            try
            {
                action();
                return (output.ToString(), error.ToString());
            }
            finally
            {
                Console.SetOut(savedOutput);
                Console.SetError(savedError);
            }
        }
    }
}
