using System.Text.Json.Nodes;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// The Resource Estimator's physical figures for one qubit model: physical qubits (algorithm and T
/// factories), runtime, the code distance of the logical qubits and the number of T factories.
/// </summary>
public sealed record PhysicalEstimate(QubitModel Model, long PhysicalQubits, double RuntimeNanoseconds, int CodeDistance, int TFactories)
{
    public static PhysicalEstimate Parse(QubitModel model, JsonNode estimate)
    {
        var counts = estimate["physicalCounts"] ?? throw new FormatException($"the estimator's result for {model} has no physicalCounts: {estimate.ToJsonString()}");
        return new PhysicalEstimate(model,
            counts["physicalQubits"]!.GetValue<long>(),
            counts["runtime"]!.GetValue<double>(),
            estimate["logicalQubit"]?["codeDistance"]?.GetValue<int>() ?? 0,
            counts["breakdown"]?["numTfactories"]?.GetValue<int>() ?? 0);
    }
}
