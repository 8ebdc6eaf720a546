namespace QuantumRayTracing.Experiments;

/// <summary>What `bench supersampling-results` measures: <paramref name="Trials"/> uniform random means per point, drawn from <paramref name="Seed"/>.</summary>
public sealed record SupersamplingResultsSettings(int Trials, ulong Seed);
