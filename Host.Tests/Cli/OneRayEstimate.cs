namespace QuantumRayTracing.Tests.Cli;

/// <summary>
/// `qrt estimate qornell-8.json --size 8 --no-circuit --workers 1 --json run.json`, run once as its own process with TERM
/// naming a colour terminal of 80 columns: <see cref="PlainOutputTests"/> reads its printed table, <see cref="JsonOutputTests"/>
/// compares the same table with its JSON record (standard output is redirected, so neither the terminal nor its width changes it).
/// </summary>
internal static class OneRayEstimate
{
    public static readonly Dictionary<string, string> ColourTerminal = new() { ["TERM"] = "xterm-256color", ["COLUMNS"] = "80" };

    private static readonly Lazy<(int Code, string Output, string Error, string Json)> Run = new(() =>
    {
        using var scratch = new ScratchDirectory("qrt-estimate-ray-");
        var scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");
        var (code, output, error) = QrtProcess.Run(ColourTerminal, scratch.Path, "estimate", scene, "--size", "8", "--no-circuit", "--workers", "1", "--json", "run.json");
        var json = File.Exists(scratch.File("run.json")) ? File.ReadAllText(scratch.File("run.json")) : "";
        return (code, output, error, json);
    });

    public static (int Code, string Output, string Error, string Json) Result => Run.Value;
}
