using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Meshes;

namespace QuantumRayTracing.Cli;

/// <summary>
/// Turns a failure into what the user sees: an exit code and one explaining line (a Q# compile error
/// keeps one line per diagnostic). Stack traces, the bridge's own output and the Q# call stack are
/// for <c>--verbose</c> only.
/// </summary>
public static class ErrorReport
{
    public static (int ExitCode, string Text) Describe(Exception e, bool verbose)
    {
        var (code, summary) = Summarise(e);
        var text = $"error: {summary}";
        if (verbose) text += Environment.NewLine + Details(e);
        else if (code != ExitCodes.BadInput) text += Environment.NewLine + "(run again with --verbose for the details)";
        return (code, text);
    }

    private static (int Code, string Summary) Summarise(Exception e) => e switch
    {
        UserError or SceneError or MeshError or SimulatorLimitException => (ExitCodes.BadInput, e.Message),
        // A file system failure after the up-front checks (a disk that filled, a directory made read-only meanwhile).
        IOException or UnauthorizedAccessException => (ExitCodes.BadInput, e.Message),
        QSharpException { Code: "compile" } q => (ExitCodes.QuantumFailure, q.Message),
        QSharpException q => (ExitCodes.QuantumFailure, $"Q# failed{(q.Location is { } at ? $" at {at}" : "")}: {FirstLine(q.Message)}"),
        BridgeException b => (ExitCodes.QuantumFailure, FirstLine(b.Message)),
        _ => (ExitCodes.InternalError, $"internal error ({e.GetType().Name}): {FirstLine(e.Message)}. This is a bug in QuantumRayTracing"),
    };

    private static string Details(Exception e)
    {
        var details = e.ToString();
        if (e is QSharpException { QSharpStack: { Length: > 0 } stack }) details = $"Q# call stack:{Environment.NewLine}{stack}{Environment.NewLine}{details}";
        return details;
    }

    private static string FirstLine(string message)
    {
        var end = message.IndexOfAny(['\r', '\n']);
        return end < 0 ? message : message[..end];
    }
}
