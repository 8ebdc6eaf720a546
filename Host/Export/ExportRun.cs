using System.Text;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Export;

/// <summary>Runs one export: checks the output file before any work, exports, then writes the whole file or nothing.</summary>
public static class ExportRun
{
    public static void Run(ExportSettings settings, TextWriter console)
    {
        EnsureWritable(settings);
        string text;
        using (var bridge = new QSharpBridge()) text = CircuitExporter.Export(bridge, settings.Subject, settings.Format);
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
