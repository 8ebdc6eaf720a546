using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `estimate oracle-sweep`: the oracle's resource estimates against the number of primitives and the coordinate bits, before and
/// after the smaller construction, with plots (docs/oracle-sweep.md); <see cref="SweepReport"/> composes the report.
/// </summary>
public static class OracleSweepExperiment
{
    public static Report Run(OracleSweepSettings settings, Action<string> progress)
    {
        var wanted = SweepReport.Wanted(settings.Primitives, settings.Bits, settings.Ablation).ToArray();
        var subjects = wanted.Select(p => (p.Primitives, p.Bits)).Distinct().ToDictionary(p => p, p => EstimateSweep.Subject(p.Primitives, p.Bits));
        // The ray tracing paper's device experiment (sec. 8): its ray, the oracle alone and the search run, as built by default and for few qubits.
        var device = SweepReport.DeviceExperimentCircuits.Select(d => (d.Circuit, new EstimateSubject(DeviceExperimentScene.Ray() with { Construction = d.Construction }, 1, "device experiment"))).ToArray();
        var jobs = wanted.Select(p => (EstimatedCircuits.Oracle, subjects[(p.Primitives, p.Bits)].With(p.Construction))).Concat(device).ToArray();

        IReadOnlyList<CircuitEstimate> estimates;
        using (var pool = new BridgePool(settings.Workers))
        {
            var done = 0;
            progress($"estimating {jobs.Length} oracles");
            // A line per tenth of the jobs keeps a log short.
            var step = Math.Max(1, jobs.Length / 10);
            estimates = new ResourceEstimator(pool, settings.Models, settings.WithCircuits).Estimate(jobs, () =>
            {
                var k = Interlocked.Increment(ref done);
                if (k % step == 0 || k == jobs.Length) progress($"estimated {k} of {jobs.Length} oracles");
            });
        }

        var points = wanted.Zip(estimates).ToDictionary(p => (p.First.Primitives, p.First.Bits, p.First.Construction.Name), p => p.Second);
        var sweep = new SweepReport(points, settings.Models, estimates.Skip(wanted.Length).ToArray());
        return sweep.ToReport(settings.Primitives, settings.Bits, settings.Ablation, SweepPlots.Draw(sweep, settings.Primitives, settings.Bits));
    }
}
