namespace QuantumRayTracing.Export;

/// <summary>The file formats `qrt export` writes.</summary>
public enum ExportFormat
{
    /// <summary>OpenQASM 2.0: unitary, every uncomputation by gates, measurement at the end.</summary>
    Qasm2,

    /// <summary>OpenQASM 3.0: the QDK's program, its measurement-based uncomputations kept as measurement and feedback.</summary>
    Qasm3,

    /// <summary>QIR (LLVM text) as the QDK compiles it, adaptive profile.</summary>
    Qir,
}
