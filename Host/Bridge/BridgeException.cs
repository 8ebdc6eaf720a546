namespace QuantumRayTracing.Bridge;

/// <summary>The Node bridge could not start, died, timed out or broke its protocol.</summary>
public class BridgeException(string message, Exception? inner = null) : Exception(message, inner);

/// <summary>A request took longer than its time limit; the bridge was stopped and restarts on next use.</summary>
public sealed class BridgeTimeoutException(string message) : BridgeException(message);

/// <summary>The bridge rejected a request as malformed (unknown method, missing field, not JSON).</summary>
public sealed class BridgeRequestException(string message) : BridgeException(message);

/// <summary>
/// Q# failed: a compile error or a runtime failure (<c>fail</c>, a failed <c>Fact</c>, a bad
/// argument). Carries the QDK's message, its source location and the Q# call stack.
/// </summary>
public sealed class QSharpException(string message, string? code, string? location, string? qsharpStack)
    : Exception(message)
{
    public string? Code { get; } = code;
    public string? Location { get; } = location;
    public string? QSharpStack { get; } = qsharpStack;
}
