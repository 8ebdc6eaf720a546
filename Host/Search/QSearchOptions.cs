namespace QuantumRayTracing.Search;

/// <summary>QSearch's parameters: the growth constant c and the rule for the bounds M_l.</summary>
public sealed record QSearchOptions(double Growth = QSearchSchedule.DefaultGrowth, MSetRule Rule = MSetRule.Ceiling);
