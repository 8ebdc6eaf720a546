using System.Globalization;
using QuantumRayTracing.Engines;
using Spectre.Console;

using QuantumRayTracing.Search;

namespace QuantumRayTracing.Views;

/// <summary>`search` on the console: the searched set and registers before the run, a progress bar during it, a table of what it found and cost after.</summary>
public static class SearchRunView
{
    /// <summary>The run, with a bar of the searches done on an interactive console (none when redirected).</summary>
    public static SearchRunResult RunWithProgress(SearchRunSettings settings) => AnsiConsole.Profile.Capabilities.Interactive
        ? AnsiConsole.Progress().AutoClear(true).Start(progress =>
        {
            var task = progress.AddTask($"{EngineFactory.Name(settings.Engine.Kind)}: searching", maxValue: settings.Searches);
            return SearchRun.Run(settings, (_, active) => task.Value = settings.Searches - active);
        })
        : SearchRun.Run(settings);

    public static void PrintPlan(SearchRunSettings settings)
    {
        var (marked, registers) = (settings.MarkedSet, settings.Registers);
        AnsiConsole.WriteLine($"N = {settings.Count}, marked = [{string.Join(", ", marked.Indices.ToArray())}] (t = {marked.MarkedCount}), M_l = {{{string.Join(", ", settings.Schedule.Bounds)}}}");
        AnsiConsole.WriteLine($"registers per search: {registers.IndexQubits} index qubits + {registers.AuxiliaryQubits} auxiliaries for the multi-controlled phase");
        AnsiConsole.WriteLine($"noise model: {settings.NoiseDescription}");
    }

    public static void Print(SearchRunSettings settings, SearchRunResult run)
    {
        var figures = run.Figures;
        var table = new Table().AddColumns("measure", "value");
        table.AddRow("searches", N(figures.Searches));
        table.AddRow("found / not found", $"{N(figures.Found)} / {N(figures.NotFound)}");
        table.AddRow("#Eval per search, conservative", Per(figures.QueriesConservativePerSearch));
        table.AddRow("#Eval per search, paper", Per(figures.QueriesPaperPerSearch));
        table.AddRow("#C_Int per search", Per(figures.ClassicalTestsPerSearch));
        table.AddRow("Grover runs per search", Per(figures.GroverRunsPerSearch));
        table.AddRow("engine calls (rounds)", N(figures.Rounds));
        table.AddRow("noise model", settings.NoiseDescription);
        table.AddRow("wall time", $"{figures.WallTime.TotalSeconds.ToString("0.000", CultureInfo.InvariantCulture)} s");
        table.AddRow("ran on", Markup.Escape(run.RanOn.Description));
        AnsiConsole.Write(table);
        AnsiConsole.MarkupLine("[grey]#Eval conservative counts r + 1 per Grover run with r ≥ 1 iterations, paper counts r; the initial sample costs none (docs/conventions.md).[/]");
    }


    private static string Per(double value) => value.ToString("0.00", CultureInfo.InvariantCulture);

    private static string N(int value) => value.ToString(CultureInfo.InvariantCulture);
}
