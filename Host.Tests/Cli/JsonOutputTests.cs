using System.Globalization;
using System.Text.RegularExpressions;
using System.Text.Json.Nodes;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Cluster;
using QuantumRayTracing.Output;
using QuantumRayTracing.Tests.Cluster;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>
/// `--json FILE` on render, search, supersample and estimate: each command runs as its own process, its printed
/// text is parsed and every figure compared with the JSON value, to the precision the text prints it with; where
/// the work ran is compared with the printed "ran on", on this machine and on a two-worker cluster in this process.
/// </summary>
public sealed partial class JsonOutputTests : IDisposable
{
    private static readonly Dictionary<string, string> NoEnvironment = [];

    private readonly ScratchDirectory _scratch = new("qrt-json-cli-");

    public void Dispose() => _scratch.Dispose();

    private (string Output, JsonObject Json) Run(params string[] args)
    {
        var (code, output, error) = QrtProcess.Run(NoEnvironment, _scratch.Path, [.. args, "--json", "run.json"]);
        Assert.True(code == 0, error);
        return (output, JsonNode.Parse(File.ReadAllText(_scratch.File("run.json")))!.AsObject());
    }

    [Fact]
    public void RenderRecordsEveryPrintedFigure()
    {
        var scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");
        // The randomized engine misses hits in a single pass without the budget, so the error figures are not all zero.
        var (output, json) = Run("render", scene, "--engine", "randomized", "--size", "16", "--seed", "5", "--passes", "1", "--budget", "0", "-o", "r.png");
        AssertRunFields(json, "render", "randomized", 5);
        Assert.Equal("16", (string?)json["options"]!["size"]);
        Assert.Equal(scene, (string?)json["options"]!["scene"]);
        var figures = json["figures"]!;

        var scenePrinted = Match(output, @"^(?<name>.+): N = (?<n>\d+) primitives, .*, (?<width>\d+)x(?<height>\d+) pixels");
        Assert.Equal(scenePrinted["name"].Value, (string?)figures["scene"]);
        Assert.Equal(Long(scenePrinted["n"].Value), (long)figures["primitives"]!);
        Assert.Equal((Long(scenePrinted["width"].Value), Long(scenePrinted["height"].Value)), ((long)figures["width"]!, (long)figures["height"]!));
        var modelled = Match(output, @"modelled per search: (?<index>\d+) index qubits \+ \d+ auxiliaries, lookup table of (?<rows>\d+) rows x (?<bits>\d+) coordinate bits");
        Assert.Equal(Long(modelled["index"].Value), (long)figures["indexQubits"]!);
        Assert.Equal(Long(modelled["rows"].Value), (long)figures["primitives"]!);
        Assert.Equal(Long(modelled["bits"].Value), (long)figures["coordinateBits"]!);
        Assert.Null(figures["gateRegisters"]);

        var table = Table(output);
        var columns = table["measure"];
        var passes = figures["passes"]!.AsArray().Append(figures["total"]).ToArray();
        Assert.Equal(columns, passes.Select(p => (string)p!["name"]!));
        for (var k = 0; k < passes.Length; k++)
        {
            var pass = passes[k]!;
            Assert.Equal(Long(table["#Rays"][k]), (long)pass["rays"]!);
            Assert.Equal(Long(table["#It"][k]), (long)pass["iterations"]!);
            Assert.Equal(Long(table["#Eval, conservative"][k]), (long)pass["cost"]!["queriesConservative"]!);
            Assert.Equal(Long(table["#Eval, paper"][k]), (long)pass["cost"]!["queriesPaper"]!);
            Assert.Equal(Long(table["#C_Int"][k]), (long)pass["cost"]!["classicalTests"]!);
            Assert.Equal(Long(table["#Int, conservative"][k]), (long)pass["intersectionsConservative"]!);
            AssertPrinted(table["Int/Ray, conservative"][k], (double)pass["perRayConservative"]!);
            AssertPrinted(table["Int/Ray, paper"][k], (double)pass["perRayPaper"]!);
            Assert.Equal(Long(table["#Cpix (neighbours)"][k]), (long)pass["updatedPixels"]!);
            Assert.Equal(Long(table["settled classically"][k]), (long)pass["settledRays"]!);
            Assert.Equal(Long(table["table rows (eval-rpc)"][k]), (long)pass["tableRows"]!);
            AssertPrinted(table["wall time"][k].Replace(" s", "", StringComparison.Ordinal), (double)pass["elapsed"]!);
        }

        var reference = Match(output, @"classical reference: (?<rays>[\d,]+) rays, Int/Ray (?<perRay>[\d.]+)");
        Assert.Equal(Long(reference["rays"].Value), (long)figures["classicalReference"]!["rays"]!);
        AssertPrinted(reference["perRay"].Value, (double)figures["classicalReference"]!["perRayConservative"]!);

        var error = Match(output, @"NRMSE (?<nrmse>[\d.]+) ?%.*#Dpix (?<dpix>\d+), %Dpix (?<share>[\d.]+) ?%");
        Assert.True((double)figures["error"]!["nrmse"]! > 0, "the randomized render should differ from the classical one");
        AssertPrinted(error["nrmse"].Value, 100 * (double)figures["error"]!["nrmse"]!);
        Assert.Equal(Long(error["dpix"].Value), (long)figures["error"]!["differentPixels"]!);
        AssertPrinted(error["share"].Value, 100 * (double)figures["error"]!["differentShare"]!);

        var wall = Match(output, @"wall time: randomized (?<render>[\d.]+) s, classical reference (?<reference>[\d.]+) s");
        AssertPrinted(wall["render"].Value, (double)figures["renderTime"]!);
        AssertPrinted(wall["reference"].Value, (double)figures["referenceTime"]!);
        Assert.Equal(["r.png"], figures["written"]!.AsArray().Select(n => (string)n!));
        Assert.Contains("wrote r.png", output, StringComparison.Ordinal);
    }

    [Fact]
    public void SearchRecordsEveryPrintedFigure()
    {
        var (output, json) = Run("search", "--engine", "analytic", "-n", "32", "-m", "3", "17", "--searches", "40");
        AssertRunFields(json, "search", "analytic", 1);
        var figures = json["figures"]!;
        Assert.Equal([3, 17], figures["marked"]!.AsArray().Select(n => (int)n!));
        var header = Match(output, @"N = (?<n>\d+), marked = \[(?<marked>[\d, ]+)\] \(t = \d+\), M_l = \{(?<bounds>[\d, ]+)\}");
        Assert.Equal(int.Parse(header["n"].Value, CultureInfo.InvariantCulture), (int)figures["count"]!);
        Assert.Equal(header["bounds"].Value, string.Join(", ", figures["bounds"]!.AsArray().Select(n => (int)n!)));

        var table = Table(output);
        Assert.Equal(Long(table["searches"][0]), (long)figures["searches"]!);
        Assert.Equal($"{(int)figures["found"]!} / {(int)figures["notFound"]!}", table["found / not found"][0]);
        AssertPrinted(table["#Eval per search, conservative"][0], (double)figures["queriesConservativePerSearch"]!);
        AssertPrinted(table["#Eval per search, paper"][0], (double)figures["queriesPaperPerSearch"]!);
        AssertPrinted(table["#C_Int per search"][0], (double)figures["classicalTestsPerSearch"]!);
        AssertPrinted(table["Grover runs per search"][0], (double)figures["groverRunsPerSearch"]!);
        Assert.Equal(Long(table["engine calls (rounds)"][0]), (long)figures["rounds"]!);
        AssertPrinted(table["wall time"][0].Replace(" s", "", StringComparison.Ordinal), (double)figures["wallTime"]!);
        // The per-search figures are the totals divided, not figures of their own.
        Assert.Equal((double)figures["total"]!["queriesConservative"]! / 40, (double)figures["queriesConservativePerSearch"]!, 12);
    }

    [Fact]
    public void SupersampleRecordsTheDeviceModelItRanUnder()
    {
        var (output, json) = Run("supersample", "--size", "4", "--subpixels", "2", "-m", "qcoin", "--device-noise", "1q=1e-2,2q=5e-2", "--readout-error", "0.02,0.1", "-o", "s.png");
        var noise = json["noise"]!;
        Assert.Equal("device, depolarizing approximation", (string?)noise["model"]);
        Assert.Equal(0.01, (double)noise["rates"]!["oneQubit"]!);
        Assert.Equal(0.05, (double)noise["rates"]!["twoQubit"]!);
        Assert.Equal(0.02, (double)noise["rates"]!["readZeroAsOne"]!);
        Assert.Equal(0.1, (double)noise["rates"]!["readOneAsZero"]!);
        Assert.Contains($"noise model: {(string?)noise["description"]}", output);
        Assert.Contains("registers: 0 subpixel + 1 coin qubits", output);
    }

    [Theory]
    [InlineData("search", "-n", "16", "-e", "analytic", "--searches", "5")]
    [InlineData("render", "--size", "8", "-o", "r.png")]
    public void SearchAndRenderRecordTheDeviceModelTheyRanUnder(params string[] arguments)
    {
        var (output, json) = Run([.. arguments, "--device-noise", "1q=1e-4,2q=1e-3", "--readout-error", "0.01,0.03"]);
        var noise = json["noise"]!;
        Assert.Equal("device, depolarizing approximation", (string?)noise["model"]);
        Assert.Equal(1e-4, (double)noise["rates"]!["oneQubit"]!);
        Assert.Equal(1e-3, (double)noise["rates"]!["twoQubit"]!);
        Assert.Equal(0.03, (double)noise["rates"]!["readOneAsZero"]!);
        Assert.Contains($"noise model: {(string?)noise["description"]}", output);
    }

    [Fact]
    public void SupersampleRecordsEveryPrintedFigure()
    {
        var (output, json) = Run("supersample", "--size", "8", "--subpixels", "4", "-m", "qss", "--seed", "3", "-o", "s.png");
        AssertRunFields(json, "supersample", "analytic", 3);
        Assert.Equal("qss", (string?)json["options"]!["method"]);
        var figures = json["figures"]!;
        var queries = Match(output, @"queries: (?<perChannel>\d+) per pixel per channel, R, G and B each; (?<total>[\d,]+) in all");
        Assert.Equal(Long(queries["perChannel"].Value), (long)figures["queriesPerChannel"]!);
        Assert.Equal(Long(queries["total"].Value), (long)figures["totalQueries"]!);
        Assert.Equal(3, (int)figures["channelsEstimated"]!);

        var error = Match(output, @"mean absolute (?<levels>[\d.]+) levels of 255 \((?<fraction>[\d.]+); (?<estimator>[\d.]+) before 8-bit rounding\), zero-error pixels (?<exact>\d+) of (?<pixels>\d+) \((?<share>[\d.]+) ?%\)");
        var e = figures["error"]!;
        AssertPrinted(error["levels"].Value, (double)e["meanLevels"]!);
        AssertPrinted(error["fraction"].Value, (double)e["meanFraction"]!);
        AssertPrinted(error["estimator"].Value, (double)e["estimatorError"]!);
        Assert.Equal(Long(error["exact"].Value), (long)e["exactPixels"]!);
        Assert.Equal(Long(error["pixels"].Value), (long)e["pixels"]!);
        AssertPrinted(error["share"].Value, 100 * (double)e["exactShare"]!);
        Assert.False(e.AsObject().ContainsKey("pixelLevels"));

        var confidence = Match(output, @"confidence: mean (?<mean>[\d.]+), lowest (?<lowest>[\d.]+)");
        AssertPrinted(confidence["mean"].Value, (double)figures["meanConfidence"]!);
        AssertPrinted(confidence["lowest"].Value, (double)figures["lowestConfidence"]!);
        AssertPrinted(Match(output, @"wall time: (?<time>[\d.]+) s on the analytic engine")["time"].Value, (double)figures["wallTime"]!);
        Assert.Equal(["s.png", "s-confidence.png"], figures["written"]!.AsArray().Select(n => (string)n!));
    }

    [Fact]
    public void EstimateRecordsThePrintedTableAndItsNumbers()
    {
        // The run PlainOutputTests reads too: `estimate qornell-8.json --size 8 --no-circuit --workers 1 --json run.json`.
        var (code, output, error, text) = OneRayEstimate.Result;
        Assert.True(code == 0, error);
        var json = JsonNode.Parse(text)!.AsObject();
        Assert.Equal("run.json", (string?)json["options"]!["json"]);
        Assert.Equal("estimate", (string?)json["command"]);
        Assert.Null(json["seed"]);
        Assert.Null(json["engine"]);
        Assert.Equal("""{"model":"none"}""", json["noise"]!.ToJsonString());
        var figures = json["figures"]!;

        var table = Table(output);
        var printed = figures["table"]!;
        Assert.Equal(table["measure"], printed["columns"]!.AsArray().Select(n => (string)n!));
        foreach (var row in printed["rows"]!.AsArray())
            Assert.Equal(table[((string)row!["measure"]!).Trim()], row["values"]!.AsArray().Select(n => (string)n!));

        var circuits = figures["circuits"]!.AsArray();
        Assert.Equal(table["measure"], circuits.Select(c => (string)c!["name"]!));
        for (var k = 0; k < circuits.Count; k++)
        {
            var circuit = circuits[k]!;
            Assert.Equal(Long(table["logical qubits (estimator)"][k]), (long)circuit["logical"]!["qubits"]!);
            Assert.Equal(Long(table["T"][k]), (long)circuit["logical"]!["t"]!);
            Assert.Equal(Long(table["CCZ"][k]), (long)circuit["logical"]!["ccz"]!);
            Assert.Equal(Long(table["measurements"][k]), (long)circuit["logical"]!["measurements"]!);
            Assert.Equal(Long(table["qubit_gate_ns_e3, surface_code: physical qubits"][k]), (long)circuit["physical"]![0]!["physicalQubits"]!);
            Assert.Equal(Long(table["qubit_gate_ns_e3, surface_code: code distance"][k]), (long)circuit["physical"]![0]!["codeDistance"]!);
        }
    }

    [Fact]
    public void RanOnIsWhereThePrintedResultsSayTheWorkRan()
    {
        var scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");
        var (render, renderJson) = Run("render", scene, "--engine", "analytic", "--size", "4", "-o", "r.png");
        AssertRanOn(Match(render, @"^analytic ran on (?<where>.+)$")["where"].Value, renderJson, RunPlace.LocalKind, bridges: 0);

        var (search, searchJson) = Run("search", "--engine", "fullstate", "-n", "8", "-s", "4", "--workers", "1");
        AssertRanOn(Table(search)["ran on"][0], searchJson, RunPlace.LocalKind, bridges: 1);

        var (supersample, supersampleJson) = Run("supersample", "--size", "2", "--subpixels", "2", "-m", "mc", "-o", "s.png");
        AssertRanOn(Match(supersample, @"; ran on (?<where>.+)$")["where"].Value, supersampleJson, RunPlace.LocalKind, bridges: 0);
    }

    [Fact]
    public void RanOnNamesTheClusterARenderRanOn()
    {
        using var first = new WorkerBridges(1);
        using var second = new WorkerBridges(1);
        using var cluster = new TestCluster(120, first, second);
        var scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");
        var (output, json) = Run("render", scene, "--engine", "fullstate", "--size", "2", "--cluster", cluster.ConfigPath, "-o", "r.png");

        var printed = Match(output, @"^fullstate ran on (?<where>.+)$")["where"].Value;
        AssertRanOn(printed, json, RunPlace.ClusterKind, bridges: 2, workers: 2);
        var clusterId = (string)JsonNode.Parse(File.ReadAllText(cluster.ConfigPath))!["clusterId"]!;
        Assert.Equal(clusterId, (string?)json["ranOn"]!["cluster"]);
        Assert.Equal("localhost", (string?)json["ranOn"]!["membership"]);
        Assert.Equal(0, (int)json["ranOn"]!["chunksSentAgain"]!);
        Assert.Equal(cluster.ConfigPath, (string?)json["options"]!["cluster"]);
    }

    /// <summary>`render --cluster` on a seeded engine sends its image to the workers: it says so, and writes the image this machine renders alone.</summary>
    [Fact]
    public void ASeededRenderOnTheClusterNamesItAndIsTheLocalImage()
    {
        using var cluster = new TestCluster(120, new WorkerExecutor(new EchoExecutor()), new WorkerExecutor(new EchoExecutor()));
        var scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");
        var (output, json) = Run("render", scene, "--engine", "analytic", "--size", "24", "--seed", "4", "--cluster", cluster.ConfigPath, "-o", "c.png");
        Run("render", scene, "--engine", "analytic", "--size", "24", "--seed", "4", "-o", "l.png");

        AssertRanOn(Match(output, @"^analytic ran on (?<where>.+)$")["where"].Value, json, RunPlace.ClusterKind, bridges: 4, workers: 2);
        Assert.True(cluster.Served(0) + cluster.Served(1) >= 1, "no worker rendered a part");
        Assert.Equal(File.ReadAllBytes(_scratch.File("l.png")), File.ReadAllBytes(_scratch.File("c.png")));
    }

    /// <summary>
    /// The JSON place is the printed one: its description is the printed text, and its kind, bridges and workers are
    /// those the text names, and those the run had (<paramref name="kind"/>, <paramref name="bridges"/>, <paramref name="workers"/>).
    /// </summary>
    private static void AssertRanOn(string printed, JsonObject json, string kind, int bridges, int? workers = null)
    {
        var ranOn = json["ranOn"]!;
        Assert.Equal(printed, (string?)ranOn["description"]);
        var local = Regex.Match(printed, @"^this machine, (?<bridges>\d+) local bridges?$");
        var cluster = Regex.Match(printed, @"^cluster '(?<id>[^']+)' \((?<membership>\w+) membership, .+\): (?<workers>\d+) workers?, (?<bridges>\d+) bridges");
        var (printedKind, printedBridges, printedWorkers) =
            printed == "this machine (no Q# bridges)" ? (RunPlace.LocalKind, 0, (int?)null)
            : local.Success ? (RunPlace.LocalKind, int.Parse(local.Groups["bridges"].Value, CultureInfo.InvariantCulture), null)
            : cluster.Success ? (RunPlace.ClusterKind, int.Parse(cluster.Groups["bridges"].Value, CultureInfo.InvariantCulture), int.Parse(cluster.Groups["workers"].Value, CultureInfo.InvariantCulture))
            : throw new Xunit.Sdk.XunitException($"'{printed}' names no place this test knows");
        Assert.Equal((printedKind, printedBridges, printedWorkers), ((string)ranOn["kind"]!, (int)ranOn["bridges"]!, (int?)ranOn["workers"]));
        Assert.Equal((kind, bridges, workers), (printedKind, printedBridges, printedWorkers));
        if (cluster.Success) Assert.Equal(cluster.Groups["id"].Value, (string?)ranOn["cluster"]);
    }

    [Fact]
    public void JsonFileNotWrittenByUsIsRefusedBeforeAnyWork()
    {
        File.WriteAllText(_scratch.File("run.json"), """{"mine": true}""");
        var (code, _, error) = QrtProcess.Run(NoEnvironment, _scratch.Path, "render", "--size", "4", "-o", "r.png", "--json", "run.json");
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.StartsWith("error: run.json: exists and was not written by this program", error, StringComparison.Ordinal);
        Assert.Equal("""{"mine": true}""", File.ReadAllText(_scratch.File("run.json")));
        Assert.Equal(["run.json"], _scratch.FileNames());

        var (same, _, sameError) = QrtProcess.Run(NoEnvironment, _scratch.Path, "render", "--size", "4", "-o", "r.json", "--json", "r.json");
        Assert.Equal(ExitCodes.BadInput, same);
        Assert.Contains("r.json", sameError, StringComparison.Ordinal);
        Assert.Equal(["run.json"], _scratch.FileNames());
    }

    private static void AssertRunFields(JsonObject json, string command, string engine, ulong seed)
    {
        Assert.Equal("qrt", (string?)json["generator"]);
        Assert.Equal(command, (string?)json["command"]);
        Assert.Equal(engine, (string?)json["engine"]);
        Assert.Equal(engine, (string?)json["options"]!["engine"]);
        Assert.Equal(seed, (ulong?)json["seed"]);
        Assert.Equal("""{"model":"none"}""", json["noise"]!.ToJsonString());
        Assert.Equal("run.json", (string?)json["options"]!["json"]);
        Assert.False(string.IsNullOrEmpty((string?)json["versions"]!["program"]));
        Assert.False(string.IsNullOrEmpty((string?)json["versions"]!["qsharpLang"]));
    }

    /// <summary>A printed number and the JSON value agree to the printed number's last digit (rounded half up or down).</summary>
    private static void AssertPrinted(string printed, double value)
    {
        var decimals = printed.Contains('.') ? printed.Length - printed.IndexOf('.') - 1 : 0;
        var parsed = double.Parse(printed, CultureInfo.InvariantCulture);
        var half = 0.5 * Math.Pow(10, -decimals);
        Assert.True(Math.Abs(parsed - value) <= half * (1 + 1e-9), $"printed {printed}, JSON {value}");
    }

    private static long Long(string printed) => long.Parse(printed, NumberStyles.AllowThousands, CultureInfo.InvariantCulture);

    private static GroupCollection Match(string output, string pattern)
    {
        var match = Regex.Match(output, pattern, RegexOptions.Multiline);
        Assert.True(match.Success, $"no line matches {pattern} in:\n{output}");
        return match.Groups;
    }

    /// <summary>A printed box table: each row's first cell → its other cells (the header row under its corner's name).</summary>
    private static Dictionary<string, string[]> Table(string output) => output.Split('\n')
        .Where(l => l.StartsWith('│'))
        .Select(l => l.Trim().Trim('│').Split('│').Select(c => c.Trim()).ToArray())
        .ToDictionary(cells => cells[0], cells => cells[1..]);
}
