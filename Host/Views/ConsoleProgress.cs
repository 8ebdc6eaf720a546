using System.Diagnostics;
using QuantumRayTracing.Passes;

using QuantumRayTracing.Rendering;

namespace QuantumRayTracing.Views;

/// <summary>
/// Progress on standard error, only once work has run longer than a second: a line rewritten in place
/// on a terminal, a line per tenth of a stage when redirected (logs stay short), with the time left in the stage (a pass,
/// or a tiled render's tiles) once it can be told.
/// </summary>
public sealed class ConsoleProgress(string label) : IRenderProgress
{
    private static readonly TimeSpan Delay = TimeSpan.FromSeconds(1);
    private readonly Stopwatch _clock = Stopwatch.StartNew();
    private readonly bool _terminal = !Console.IsErrorRedirected;
    private string _lastLine = "";
    private string? _stage;
    private TimeSpan _stageStart;
    private bool _wroteInPlace;

    public void Report(string stage, double done)
    {
        if (stage != _stage) (_stage, _stageStart) = (stage, _clock.Elapsed);
        if (_clock.Elapsed < Delay) return;
        var percent = (int)Math.Floor(Math.Clamp(done, 0, 1) * 100);
        // Redirected, a line per tenth of a pass: the time left rides along, it does not add lines.
        // The stage as its reporter names it: a pass ("shadow"), a tiled render's tiles ("64 tiles"), the supersampler.
        var step = $"{label}: {stage} {(_terminal ? percent : percent / 10 * 10)}%";
        var line = step + Left(done);
        if ((_terminal ? line : step) == _lastLine) return;
        _lastLine = _terminal ? line : step;
        if (_terminal)
        {
            Console.Error.Write("\r" + line.PadRight(90));
            _wroteInPlace = true;
        }
        else Console.Error.WriteLine(line);
    }

    // The stage's time left at its pace so far, once it has run long enough to say (a few seconds and a tenth of its work).
    private string Left(double done)
    {
        var elapsed = (_clock.Elapsed - _stageStart).TotalSeconds;
        if (elapsed < 3 || done < 0.1 || done >= 1) return "";
        var left = elapsed * (1 - done) / done;
        return FormattableString.Invariant($", about {Math.Ceiling(left):F0} s left");
    }

    /// <summary>Clears the in-place line so the results print on a clean line.</summary>
    public void Finish()
    {
        if (_wroteInPlace) Console.Error.Write("\r" + new string(' ', 90) + "\r");
        _wroteInPlace = false;
    }
}
