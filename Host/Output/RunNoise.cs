namespace QuantumRayTracing.Output;

/// <summary>
/// The noise model a result was obtained under, as its reports name it: a model name and its rates (for Pauli
/// noise px, py, pz per gate and the qubit loss) and how the printed results describe it. <see cref="None"/> for a
/// noiseless run.
/// </summary>
public sealed record RunNoise(string Model, IReadOnlyDictionary<string, double>? Rates = null, string? Description = null)
{
    public static readonly RunNoise None = new("none");
}
