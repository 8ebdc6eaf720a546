using System.CommandLine;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Cli;

/// <summary>The options `estimate` and `estimate oracle-sweep` share: oracle construction, qubit models, circuit extraction, workers, format.</summary>
public sealed class EstimateOptions
{
    public readonly Option<string> Oracle = new Option<string>("--oracle")
    {
        Description = "How the oracle is built: baseline (x, y and z tested, minimum then maximum in one register), compact (only the two in-plane axes, both bounds at once; the default), narrow (compact, unloading by lookup instead of measurement: more Toffolis, fewer auxiliary qubits) or device (no bound or valid qubit: each primitive's bounds compared as constants under index control; the fewest qubits, more gates as N grows).",
        DefaultValueFactory = _ => OracleConstruction.Default.Name,
        HelpName = string.Join('|', OracleConstruction.Named.Select(c => c.Name)),
    }.Must(name => OracleConstruction.Named.All(c => c.Name != name) ? $"--oracle: unknown construction '{name}'; choose {string.Join(", ", OracleConstruction.Named.Select(c => c.Name))}" : null);

    public readonly Option<string[]> Models = new("--models")
    {
        Description = $"Resource Estimator qubit models, NAME or NAME:QEC_SCHEME, space-separated (names: {string.Join(", ", QubitModel.Names)}; schemes: surface_code, floquet_code for Majorana models). Default: {string.Join(" ", QubitModel.Defaults.Select(m => $"{m.Name}:{m.QecScheme}"))}.",
        AllowMultipleArgumentsPerToken = true,
        DefaultValueFactory = _ => QubitModel.Defaults.Select(m => $"{m.Name}:{m.QecScheme}").ToArray(),
    };

    public readonly Option<bool> NoCircuit = new("--no-circuit")
    {
        Description = "Skip getCircuit (gates by kind and depth), which simulates the circuit once; keep the estimator's counts.",
    };

    public readonly Option<ReportFormat> Format = new Option<ReportFormat>("--format")
    {
        Description = "table (console), md (Markdown) or csv.",
        DefaultValueFactory = _ => ReportFormat.Table,
        HelpName = "table|md|csv",
    }.Choices();

    public readonly Option<int> Workers = CommonOptions.Workers("Node bridge processes estimating circuits in parallel. Default: the core count.");

    public EstimateOptions() =>
        Models.Validators.Add(r =>
        {
            var texts = r.GetValueOrDefault<string[]>() ?? [];
            if (texts.Length == 0) r.AddError("--models: name at least one qubit model");
            foreach (var text in texts)
                if (QubitModel.Parse(text) is { Error: { } error }) r.AddError($"--models: {error}");
        });

    public void AddTo(Command command, bool withFormat = true)
    {
        command.AddOptions(Oracle, Models, NoCircuit);
        if (withFormat) command.Options.Add(Format);
        command.Options.Add(Workers);
    }

    public OracleConstruction Construction(ParseResult parse) => OracleConstruction.Named.Single(c => c.Name == parse.GetValue(Oracle));

    public IReadOnlyList<QubitModel> QubitModels(ParseResult parse) => parse.GetValue(Models)!.Select(t => QubitModel.Parse(t).Model!).ToArray();
}
