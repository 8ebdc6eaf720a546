using QuantumRayTracing.Cli;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>Runs a command with standard error captured; one run at a time, since the console's error writer is global.</summary>
internal static class ConsoleCapture
{
    private static readonly Lock Gate = new();

    public static (int Code, string Error) Run(params string[] args)
    {
        lock (Gate)
        {
            var saved = Console.Error;
            var error = new StringWriter();
            Console.SetError(error);
            try
            {
                return (CommandLine.Run(args), error.ToString());
            }
            finally
            {
                Console.SetError(saved);
            }
        }
    }
}
