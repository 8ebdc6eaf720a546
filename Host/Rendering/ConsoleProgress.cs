using System.Diagnostics;
using QuantumRayTracing.Passes;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// Progress on standard error, only once work has run longer than a second: a line rewritten in place
/// on a terminal, a line per tenth of a stage when redirected (logs stay short).
/// </summary>
public sealed class ConsoleProgress(string label) : IRenderProgress
{
    private static readonly TimeSpan Delay = TimeSpan.FromSeconds(1);
    private readonly Stopwatch _clock = Stopwatch.StartNew();
    private readonly bool _terminal = !Console.IsErrorRedirected;
    private string _lastLine = "";
    private bool _wroteInPlace;

    public void Report(string stage, double done)
    {
        if (_clock.Elapsed < Delay) return;
        var percent = (int)Math.Floor(Math.Clamp(done, 0, 1) * 100);
        var line = $"{label}: {stage} pass {(_terminal ? percent : percent / 10 * 10)}%";
        if (line == _lastLine) return;
        _lastLine = line;
        if (_terminal)
        {
            Console.Error.Write("\r" + line.PadRight(60));
            _wroteInPlace = true;
        }
        else Console.Error.WriteLine(line);
    }

    /// <summary>Clears the in-place line so the results print on a clean line.</summary>
    public void Finish()
    {
        if (_wroteInPlace) Console.Error.Write("\r" + new string(' ', 60) + "\r");
        _wroteInPlace = false;
    }
}
