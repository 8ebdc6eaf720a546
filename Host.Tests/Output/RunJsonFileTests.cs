using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Output;

/// <summary>The --json document: its fixed fields, how a file is recognised as ours, and the output rules.</summary>
public sealed class RunJsonFileTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-json-");

    public void Dispose() => _scratch.Dispose();

    private sealed record Figures(long Rays, double Share, TimeSpan Elapsed, int[] Ids, string? Missing = null);

    private static readonly RunRecord Run = new("render", new Dictionary<string, object?> { ["size"] = "16", ["reference"] = false, ["max-qubits"] = null },
        7, "analytic", RunNoise.None, new Figures(835, 0.25, TimeSpan.FromMilliseconds(1500), [3, 1]));

    [Fact]
    public void DocumentHoldsTheRunTheVersionsAndTheNoiseModel()
    {
        var text = RunJsonFile.Compose(Run, new ToolVersions("1.2.3", "1.32.5-dev", null, "could not start 'node'"));
        var document = JsonNode.Parse(text)!.AsObject();
        Assert.Equal("qrt", (string?)document["generator"]);
        Assert.Equal("render", (string?)document["command"]);
        Assert.Equal("docs/conventions.md", (string?)document["conventions"]);
        Assert.Equal(7UL, (ulong?)document["seed"]);
        Assert.Equal("analytic", (string?)document["engine"]);
        Assert.Equal("""{"model":"none"}""", document["noise"]!.ToJsonString());
        Assert.Equal("1.2.3", (string?)document["versions"]!["program"]);
        Assert.Equal("1.32.5-dev", (string?)document["versions"]!["qsharpLang"]);
        Assert.Null(document["versions"]!["node"]);
        Assert.Equal("could not start 'node'", (string?)document["versions"]!["nodeProblem"]);
        Assert.Equal("16", (string?)document["options"]!["size"]);
        Assert.False((bool)document["options"]!["reference"]!);
        Assert.True(document["options"]!.AsObject().ContainsKey("max-qubits"));
        var figures = document["figures"]!;
        Assert.Equal(835L, (long)figures["rays"]!);
        Assert.Equal(0.25, (double)figures["share"]!);
        Assert.Equal(1.5, (double)figures["elapsed"]!);  // durations in seconds, as printed
        Assert.Equal([3, 1], figures["ids"]!.AsArray().Select(n => (int)n!));
        Assert.False(figures.AsObject().ContainsKey("missing"));
    }

    [Fact]
    public void NoiseModelWithRatesIsRecorded()
    {
        var noisy = Run with { Noise = new RunNoise("pauli", new Dictionary<string, double> { ["px"] = 0.001, ["py"] = 0, ["pz"] = 0.002 }) };
        var noise = JsonNode.Parse(RunJsonFile.Compose(noisy, new ToolVersions("1", null, "v20.0.0", null)))!["noise"]!;
        Assert.Equal("pauli", (string?)noise["model"]);
        Assert.Equal(0.002, (double)noise["rates"]!["pz"]!);
    }

    [Fact]
    public void WhereTheWorkRanIsRecordedWhenNamed()
    {
        var versions = new ToolVersions("1", null, null, null);
        Assert.False(JsonNode.Parse(RunJsonFile.Compose(Run, versions))!.AsObject().ContainsKey("ranOn"));

        var onCluster = Run with { RanOn = new RunPlace("cluster 'lab' (redis membership, lab.json): 3 workers, 24 bridges", RunPlace.ClusterKind, 24, "lab", "redis", 3, 0) };
        var ranOn = JsonNode.Parse(RunJsonFile.Compose(onCluster, versions))!["ranOn"]!;
        Assert.Equal("cluster 'lab' (redis membership, lab.json): 3 workers, 24 bridges", (string?)ranOn["description"]);
        Assert.Equal(("cluster", 24, 3, "lab", "redis", 0), ((string)ranOn["kind"]!, (int)ranOn["bridges"]!, (int)ranOn["workers"]!, (string)ranOn["cluster"]!, (string)ranOn["membership"]!, (int)ranOn["chunksSentAgain"]!));

        var local = JsonNode.Parse(RunJsonFile.Compose(Run with { RanOn = RunPlace.LocalBridges(2) }, versions))!["ranOn"]!;
        Assert.Equal("""{"description":"this machine, 2 local bridges","kind":"local","bridges":2}""", local.ToJsonString());
    }

    [Fact]
    public void OnlyAJsonObjectGeneratedByQrtIsOurs()
    {
        string Write(string name, string text)
        {
            var path = _scratch.File(name);
            File.WriteAllText(path, text);
            return path;
        }
        Assert.True(RunJsonFile.IsOurs(Write("ours.json", RunJsonFile.Compose(Run, new ToolVersions("1", null, null, null)))));
        Assert.False(RunJsonFile.IsOurs(Write("other.json", """{"generator": "someone else", "figures": {}}""")));
        Assert.False(RunJsonFile.IsOurs(Write("nested.json", """{"data": {"generator": "qrt"}}""")));
        Assert.False(RunJsonFile.IsOurs(Write("array.json", """[{"generator": "qrt"}]""")));
        Assert.False(RunJsonFile.IsOurs(Write("text.json", "generator: qrt")));
        Assert.False(RunJsonFile.IsOurs(Write("empty.json", "")));
        Assert.False(RunJsonFile.IsOurs(Write("later.json", """{"figures": {}, "generator": "qrt"}""")));
        Assert.True(RunJsonFile.IsOurs(Write("compact.json", """{"generator":"qrt"}""")));
    }

    [Fact]
    public void AFileThatIsNotOursIsNeverReplaced()
    {
        var path = _scratch.File("results.json");
        File.WriteAllText(path, """{"mine": true}""");
        var refusal = Assert.Throws<UserError>(() => RunJsonFile.EnsureWritable(path, []));
        Assert.StartsWith($"{path}: exists and was not written by this program", refusal.Message, StringComparison.Ordinal);
        Assert.Equal("""{"mine": true}""", File.ReadAllText(path));

        File.WriteAllText(path, RunJsonFile.Compose(Run, new ToolVersions("1", null, null, null)));
        RunJsonFile.EnsureWritable(path, []);
        var clash = Assert.Throws<UserError>(() => RunJsonFile.EnsureWritable(path, [_scratch.File("x.png"), path]));
        Assert.StartsWith($"{path}: --json names a file this command already reads or writes", clash.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void WriteReplacesItsOwnFileWhole()
    {
        var path = _scratch.File("run.json");
        RunJsonFile.Write(path, Run);
        RunJsonFile.Write(path, Run with { Seed = 8 });
        Assert.Equal(8UL, (ulong?)JsonNode.Parse(File.ReadAllText(path))!["seed"]);
        Assert.Equal(["run.json"], _scratch.FileNames());
        RunJsonFile.Write(null, Run);  // no --json: nothing written
        Assert.Equal(["run.json"], _scratch.FileNames());
    }
}
