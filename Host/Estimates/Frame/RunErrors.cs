using System.Text.Json.Nodes;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// What the Resource Estimator reports about how one execution can fail: the logical error rate per
/// logical qubit and logical cycle, the logical qubits after layout and the cycles (logical depth);
/// the T states consumed and each one's error rate after distillation; and the share of the budget
/// left to rotation synthesis.
/// </summary>
public sealed record RunErrors(double LogicalErrorRate, long LogicalQubits, long LogicalDepth, long TStates, double TStateErrorRate, double RotationBudget)
{
    /// <summary>
    /// A union bound on the probability that the execution fails: any logical qubit failing in any
    /// cycle, any T state being faulty, or any rotation's synthesis error (at most its budget share).
    /// </summary>
    public double FailureBound => LogicalErrorRate * LogicalQubits * LogicalDepth + TStateErrorRate * TStates + RotationBudget;

    public static RunErrors? Parse(JsonNode estimate)
    {
        var breakdown = estimate["physicalCounts"]?["breakdown"];
        var rate = estimate["logicalQubit"]?["logicalErrorRate"];
        if (breakdown is null || rate is null) return null;
        var tStates = breakdown["numTstates"]?.GetValue<long>() ?? 0;
        // No T factory when there are no T states; otherwise the factory's output error rate.
        var tRate = tStates == 0 ? 0 : estimate["tfactory"]?["logicalErrorRate"]?.GetValue<double>() ?? double.NaN;
        return new RunErrors(rate.GetValue<double>(),
            breakdown["algorithmicLogicalQubits"]!.GetValue<long>(),
            breakdown["logicalDepth"]!.GetValue<long>(),
            tStates, tRate,
            estimate["errorBudget"]?["rotations"]?.GetValue<double>() ?? 0);
    }
}
