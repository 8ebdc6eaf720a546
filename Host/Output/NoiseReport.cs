namespace QuantumRayTracing.Output;

/// <summary>
/// The noise model a result was obtained under, as its reports name it: a model name and its rates (for Pauli
/// noise px, py, pz per gate and the qubit loss). <see cref="None"/> for the noiseless engines.
/// </summary>
public sealed record NoiseReport(string Model, IReadOnlyDictionary<string, double>? Rates = null)
{
    public static readonly NoiseReport None = new("none");
}
