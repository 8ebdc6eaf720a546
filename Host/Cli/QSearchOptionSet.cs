using System.CommandLine;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Cli;

/// <summary>QSearch's options, shared by every command that runs it: --growth and --m-rule.</summary>
public sealed class QSearchOptionSet
{
    public readonly Option<double> Growth = new Option<double>("--growth", "-c")
    {
        Description = "QSearch's growth constant c, 1 < c < 2.",
        DefaultValueFactory = _ => QSearchSchedule.DefaultGrowth,
    }.Must(c => c > 1 && c < 2 ? null : $"--growth must satisfy 1 < c < 2, got {c}");

    public readonly Option<MSetRule> Rule = new Option<MSetRule>("--m-rule")
    {
        Description = "How the bounds M_l grow: ceiling (Algorithm 1: ceil(c^l) from l = 1, capped at ceil(sqrt N)) or round (the paper's table 6: round(c^l) from l = 0, below ceil(sqrt N)).",
        DefaultValueFactory = _ => MSetRule.Ceiling,
        HelpName = "ceiling|round",
    }.Choices();

    public void AddTo(Command command) => command.AddOptions(Growth, Rule);

    public QSearchOptions Get(ParseResult parse) => new(parse.GetValue(Growth), parse.GetValue(Rule));
}
