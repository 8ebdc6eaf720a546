using System.Text;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Export;

/// <summary>Runs one export: checks the output file before any work, exports, then writes the whole file or nothing.</summary>
public static class ExportRun
{
    /// <summary>
    /// A running bridge the exports on this call's flow use instead of starting one each (null: start one): the
    /// tests export dozens of circuits through the command line, and a bridge's start-up and first requests cost
    /// more than a small circuit's export.
    /// </summary>
    internal static readonly AsyncLocal<QSharpBridge?> SharedBridge = new();

    public static void Run(ExportSettings settings, TextWriter console)
    {
        EnsureWritable(settings);
        string text;
        if (SharedBridge.Value is { } shared) text = CircuitExporter.Export(shared, settings.Subject, settings.Format);
        else using (var bridge = new QSharpBridge()) text = CircuitExporter.Export(bridge, settings.Subject, settings.Format);
        if (settings.Output is { } path) AtomicFile.WriteAllBytes(path, Encoding.UTF8.GetBytes(text));
        else console.Write(text);
    }

    private static void EnsureWritable(ExportSettings settings)
    {
        if (settings.Output is not { } path) return;
        if (Directory.Exists(path)) throw new UserError($"-o {path}: is a directory");
        if (File.Exists(path) && !settings.Force) throw new UserError($"-o {path}: the file exists; give --force to replace it");
        if (!Directory.Exists(Path.GetDirectoryName(Path.GetFullPath(path)))) throw new UserError($"-o {path}: the directory does not exist");
        if (AtomicFile.CannotCreateBeside(path) is { } why) throw new UserError($"-o {path}: cannot write there ({why})");
    }
}
