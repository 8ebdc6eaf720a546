using System.CommandLine;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Output;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What every `bench` command that writes a report to docs/ shares: the scene directory, the seed, the
/// bridge count, the cluster, the output file (replaced only if this command wrote it) and its CSV tables.
/// </summary>
public sealed class BenchReportOptions(string commandLine, string outputExample)
{
    public readonly Option<DirectoryInfo> SceneDirectory = CommonOptions.SceneDirectory();

    public readonly Option<ulong> Seed = CommonOptions.Seed("Seed of every render and simulation.");

    public readonly Option<int> Workers = CommonOptions.Workers("Node bridges for the Q# engines. Default: the core count.");

    public readonly Option<FileInfo?> Output = CommonOptions.ReportOutput(
        $"Write the Markdown report here (e.g. {outputExample}). It replaces only a report this command wrote before. Default: the report is printed only.");

    public readonly Option<FileInfo?> Cluster = CommonOptions.LocalBridgesOrCluster();

    public readonly Option<bool> Csv = new("--csv")
    {
        Description = "Also write every table of the report as CSV beside it (<report>-<table>.csv), for scripts. Needs --output.",
    };

    /// <summary>Adds the shared options; <paramref name="cluster"/> for experiments that run Q# engines, no <paramref name="workers"/> for those that start no bridges.</summary>
    public void AddTo(Command command, bool scenes = true, bool seed = true, bool cluster = false, bool workers = true)
    {
        if (scenes) command.Options.Add(SceneDirectory);
        if (seed) command.Options.Add(Seed);
        if (workers) command.Options.Add(Workers);
        if (cluster) command.Options.Add(Cluster);
        command.AddOptions(Output, Csv);
    }

    /// <summary>The report's writer, its Markdown file checked writable before any work starts.</summary>
    public ReportWriter Writer(ParseResult parse)
    {
        if (parse.GetValue(Csv) && parse.GetValue(Output) is null) throw new UserError("--csv: the tables are written beside the report; name it with --output");
        var writer = new ReportWriter(parse.GetValue(Output)?.FullName, commandLine, parse.GetValue(Csv));
        writer.EnsureWritable();
        return writer;
    }

    /// <summary>
    /// The cluster's bridges when <c>--cluster</c> names a file, null otherwise (the experiment's Q# engines then
    /// start local bridges). Connecting fails with one line and exit code 3.
    /// </summary>
    public BridgePool? StartBridges(ParseResult parse) =>
        parse.GetValue(Cluster) is { } file ? QuantumRayTracing.Cluster.ClusterBridges.Start(file.FullName, parse.GetValue(Workers)) : null;

    /// <summary>The scene <paramref name="stem"/>.json from the scene directory.</summary>
    public Scene Load(ParseResult parse, string stem) => SceneLoader.Load(Path.Combine(parse.GetValue(SceneDirectory)!.FullName, stem + ".json"));
}
