using QuantumRayTracing.Passes;

namespace QuantumRayTracing.Rendering;

/// <summary>Progress of a run made of several renders in turn (the engine's, then the references'), each under its own label.</summary>
public interface IRunProgress
{
    /// <summary>The render named <paramref name="label"/> starts: its passes report to the progress returned.</summary>
    IRenderProgress Start(string label);

    /// <summary>The render started last has ended, or failed.</summary>
    void Finish();
}
