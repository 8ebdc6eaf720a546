namespace QuantumRayTracing.Cli;

/// <summary>Every exit code `qrt` returns; scripts and CI tell failures apart by them.</summary>
public static class ExitCodes
{
    /// <summary>The command did what it was asked.</summary>
    public const int Success = 0;

    /// <summary>The command line does not parse or asks for something impossible (System.CommandLine's own code for a parse error).</summary>
    public const int UsageError = 1;

    /// <summary>A scene file, an image, an output path, an option's value or a request too large for the simulator.</summary>
    public const int BadInput = 2;

    /// <summary>Node.js, the bridge, the cluster or Q# failed.</summary>
    public const int QuantumFailure = 3;

    /// <summary>A bug in QuantumRayTracing.</summary>
    public const int InternalError = 4;

    /// <summary>`bench soak`: a render failed one of its checks.</summary>
    public const int ChecksFailed = 5;
}
