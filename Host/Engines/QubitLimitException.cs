using System.Globalization;
using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Engines;

/// <summary>
/// A gate-level search would need more qubits than the engine was allowed (<see cref="GateEngine.MaxQubits"/>):
/// raised before any of the batch reaches the simulator. One line naming the ray, its width and the limit.
/// </summary>
public sealed class QubitLimitException(OracleInput input, OracleRegisters registers, int limit) : SimulatorLimitException(Describe(input, registers, limit))
{
    public OracleInput Input => input;

    public OracleRegisters Registers => registers;

    public int Limit => limit;

    private static string Describe(OracleInput input, OracleRegisters r, int limit)
    {
        var ray = input.Table.Ray;
        return string.Create(CultureInfo.InvariantCulture,
            $"the gate-level search of the ray from {ray.Origin} along {ray.Direction} needs {r.PeakQubits} qubits at peak ({r.IndexQubits} index + {r.WorkQubits} work + {OracleRegisters.OutputQubits} phase + {r.AuxiliaryQubits} auxiliary, {input.Construction} oracle), more than the limit of {limit} (--max-qubits)");
    }
}
