using QuantumRayTracing.Passes;

using QuantumRayTracing.Rendering;

namespace QuantumRayTracing.Views;

/// <summary>A run's renders on standard error, one <see cref="ConsoleProgress"/> each, its line cleared when the render ends.</summary>
public sealed class ConsoleRunProgress : IRunProgress
{
    private ConsoleProgress? _current;

    public IRenderProgress Start(string label) => _current = new ConsoleProgress(label);

    public void Finish()
    {
        _current?.Finish();
        _current = null;
    }
}
