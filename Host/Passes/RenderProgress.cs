namespace QuantumRayTracing.Passes;

/// <summary>Where passes report how far they are: a stage name and the share of its work done, in [0, 1].</summary>
public interface IRenderProgress
{
    void Report(string stage, double done);
}
