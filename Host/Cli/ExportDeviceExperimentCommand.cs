using System.CommandLine;
using QuantumRayTracing.Export;

namespace QuantumRayTracing.Cli;

/// <summary>`export device-experiment`: the ray tracing paper's sec. 8 search, the circuit of its fig. 15.</summary>
public sealed class ExportDeviceExperimentCommand : Command
{
    private readonly ExportOutputOptions _output = new();

    public ExportDeviceExperimentCommand() : base("device-experiment", "The ray tracing paper's sec. 8 device experiment (its fig. 15): 4 primitives, the ray that meets one, one Grover iteration, with the narrow oracle.")
    {
        _output.AddTo(this, _ => DeviceExperimentExport.Subject());
    }
}
