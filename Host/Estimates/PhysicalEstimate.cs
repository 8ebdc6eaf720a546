using System.Text.Json.Nodes;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// The Resource Estimator's physical figures for one qubit model: physical qubits (algorithm and T
/// factories), runtime, the code distance of the logical qubits and the number of T factories; and
/// what it reports of the run's errors (<see cref="Errors"/>).
/// </summary>
public sealed record PhysicalEstimate(QubitModel Model, long PhysicalQubits, double RuntimeNanoseconds, int CodeDistance, int TFactories)
{
    /// <summary>The figures behind the run's failure probability; null when the estimator did not report them.</summary>
    public RunErrors? Errors { get; init; }

    public static PhysicalEstimate Parse(QubitModel model, JsonNode estimate)
    {
        var counts = estimate["physicalCounts"] ?? throw new FormatException($"the estimator's result for {model} has no physicalCounts: {estimate.ToJsonString()}");
        return new PhysicalEstimate(model,
            counts["physicalQubits"]!.GetValue<long>(),
            counts["runtime"]!.GetValue<double>(),
            estimate["logicalQubit"]?["codeDistance"]?.GetValue<int>() ?? 0,
            counts["breakdown"]?["numTfactories"]?.GetValue<int>() ?? 0)
        {
            Errors = RunErrors.Parse(estimate),
        };
    }
}
