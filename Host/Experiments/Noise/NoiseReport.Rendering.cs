using QuantumRayTracing.Estimates;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>The rendering-under-noise section of docs/noise.md.</summary>
public static partial class NoiseReport
{
    /// <summary>
    /// Rendering under noise on the gate-level oracle's model and beside it the lookup oracle's, the thresholds of each, and the
    /// confirmations on the noisy gate engine.
    /// </summary>
    public static void Render(Report report, IReadOnlyList<NoisyRenderBenchmark.Sweep> sweeps, int size, IReadOnlyList<(string Scene, double PerGate, RenderMeasurement Analytic, RenderMeasurement FullState)> confirmations, int confirmSize)
    {
        report.Heading("Rendering under noise");
        var pipeline = NoisyRenderBenchmark.Defaults(size);
        report.Text(Lines(
            $"The default pipeline of `render` (neighbours, exact termination, a lattice of {pipeline.LatticeLevels} levels from the image size, agreed-miss {F(pipeline.AgreedMiss, "0.###")}, up to {pipeline.Iterations} rounds,",
            $"and the misses the accuracy budget asks of rays no lattice neighbour vouches for) at {size}x{size} on the analytic engine under",
            "the analytic model of depolarizing Pauli noise p per gate and qubit, seed 1, once for each oracle's circuit:",
            "- **gate-level oracle** (`--noise-oracle gate-level`, the default): the circuit a machine would run and `qrt estimate` prices, its harm",
            "  counted location by location (the exposure table above; scenes of the same N and coordinate bits share one traced circuit);",
            "- **lookup oracle** (`--noise-oracle lookup`): an oracle over intersection answers computed classically beforehand, which leaves out",
            "  the cost and the noise of computing them; its circuit evolved exactly as a density matrix (the model check above), once per",
            "  marked count the render asks, and kept for the process;",
            "- **gate-level, noise-aware** (`render`'s default under noise): the gate-level oracle's model, and the passes (termination rule, lattice",
            "  confirmations, accuracy budget, classical settling) plan with each run's noisy success instead of the ideal one, so a ray whose",
            "  noisy search would cost more than N classical tests is settled classically.",
            "Int/Ray in the conservative count (r + 1 per Grover run, every classical test counted); NRMSE against the classical",
            "render of the same options (RMS of 8-bit channel differences over the reference's range); #Dpix pixels whose 8-bit colour differs.",
            "QSearch verifies every candidate, so noise never makes a false hit: it lowers the success probability of each Grover run,",
            "which costs queries, and it makes the termination rule and the lattice's cheap confirmations (which assume the ideal miss",
            "rates) stop searches that would have hit, which costs pixels; planned with the noisy rates, it costs queries instead.",
            "Wall time: the fastest of three identical renders (same seed), and the first of them, which under the lookup oracle's model",
            "also evolves its circuits (the later ones find them kept, as every render after the first in one process does); vs noiseless:",
            "the fastest against the fastest p = 0 render of the same sweep."));
        var thresholds = new TextTable("thresholds", ["scene", "noise model from", "(a) loses to brute force in Int/Ray at p ≈", "(b) loses to the randomized renderer at equal Int/Ray at p ≈"]);
        foreach (var sweep in sweeps)
        {
            var classicalPerRay = sweep.Classical.Result.Total.PerRayConservative;
            var ideal = sweep.Quantum.First(q => q.PerGate == 0).Measurement;
            var (oracle, slug) = (sweep.Label, sweep.Slug);
            report.Heading($"{sweep.Scene}, {oracle}", 3);
            report.Text($"Classical brute force: Int/Ray {F(classicalPerRay, "0.00")}. Noise model: the {sweep.Oracle.Description()}"
                + (sweep.NoiseAware ? "; the passes plan with the noisy runs' success (`render`'s default under noise)." : "; the passes plan with the ideal miss rates (`--ideal-plan`)."));
            var quantum = new TextTable($"render-{sweep.Scene}-{slug}", ["p per gate", "Int/Ray", "NRMSE", "#Dpix", "randomized NRMSE at equal Int/Ray", "wall time", "first of three", "vs noiseless"]);
            foreach (var q in sweep.Quantum)
            {
                var m = q.Measurement;
                var randomized = sweep.RandomizedNrmseAt(m.Result.Total.PerRayConservative);
                quantum.Row(Rate(q.PerGate), F(m.Result.Total.PerRayConservative, "0.00"), F(m.Error.Nrmse * 100, "0.00") + " %", I(m.Error.DifferentPixels),
                    randomized is { } r ? F(r * 100, "0.00") + " %" : "outside its range", F(m.WallTime.TotalSeconds, "0.00") + " s", F(q.FirstWallTime.TotalSeconds, "0.00") + " s", F(m.WallTime / ideal.WallTime, "0.0") + "x");
            }
            report.Table(quantum);
            var a = sweep.Crossing(q => q.Measurement.Result.Total.PerRayConservative - classicalPerRay);
            var b = sweep.Crossing(q => sweep.RandomizedNrmseAt(q.Measurement.Result.Total.PerRayConservative) is { } r ? q.Measurement.Error.Nrmse - r : double.NaN);
            var highest = Rate(sweep.Quantum.Max(q => q.PerGate));
            var (aText, bText) = Thresholds(sweep);
            thresholds.Row(sweep.Scene, oracle, aText, bText);
            report.Text(Lines(
                $"With the {sweep.Oracle.Name()} oracle's noise model{(sweep.NoiseAware ? ", the passes planning with it" : "")}:",
                "- (a) quantum loses to classical brute force in Int/Ray " + (a is { } x2 ? $"at p ≈ {Rate(x2)} per gate;" : $"at no rate up to p = {highest} (its Int/Ray stays below {F(classicalPerRay, "0")});"),
                "- (b) quantum loses to the randomized renderer at equal Int/Ray in NRMSE " + (b is { } y2 ? $"at p ≈ {Rate(y2)} per gate." : $"at no rate up to p = {highest}.")));
            if (sweep.Oracle == NoiseOracle.GateLevel && !sweep.NoiseAware)
            {
                report.Text(Lines(
                    "The randomized renderer (floor(sqrt N) random primitives per ray and pass; the same pipeline without the termination rule,",
                    "which would stop its rays after a miss or two and cap its Int/Ray below the quantum one) at 1 … " + sweep.Randomized.Count + " passes; its NRMSE at the",
                    "quantum Int/Ray above is interpolated linearly between these (the same renders serve both oracles):"));
                var randomizedTable = new TextTable($"randomized-{sweep.Scene}", ["passes", "Int/Ray", "NRMSE", "#Dpix"]);
                foreach (var (passes, m) in sweep.Randomized)
                    randomizedTable.Row(I(passes), F(m.Result.Total.PerRayConservative, "0.00"), F(m.Error.Nrmse * 100, "0.00") + " %", I(m.Error.DifferentPixels));
                report.Table(randomizedTable);
            }
            report.Plot($"render-{sweep.Scene}-{slug}", NoisePlots.LogX($"{sweep.Scene}, {size}x{size}, {oracle}: NRMSE against per-gate error (analytic)", "per-gate error p", "NRMSE (%)",
                [("quantum, default pipeline", sweep.Quantum.Where(q => q.PerGate > 0).Select(q => (q.PerGate, q.Measurement.Error.Nrmse * 100)).ToArray()),
                 ("randomized at equal Int/Ray", sweep.Quantum.Where(q => q.PerGate > 0 && sweep.RandomizedNrmseAt(q.Measurement.Result.Total.PerRayConservative) is not null)
                    .Select(q => (q.PerGate, sweep.RandomizedNrmseAt(q.Measurement.Result.Total.PerRayConservative)!.Value * 100)).ToArray())]),
                $"{sweep.Scene}: NRMSE against the per-gate error, {oracle}");
            report.Plot($"int-per-ray-{sweep.Scene}-{slug}", NoisePlots.LogX($"{sweep.Scene}, {size}x{size}, {oracle}: Int/Ray against per-gate error (analytic)", "per-gate error p", "Int/Ray (conservative)",
                [("quantum, default pipeline", sweep.Quantum.Where(q => q.PerGate > 0).Select(q => (q.PerGate, q.Measurement.Result.Total.PerRayConservative)).ToArray())],
                classicalPerRay, "classical brute force"),
                $"{sweep.Scene}: Int/Ray against the per-gate error, {oracle}");
        }
        if (sweeps.Count > 0)
        {
            report.Heading("Thresholds", 3);
            report.Text($"Where quantum rendering loses, {size}x{size}, default pipeline, per oracle (log-linear between the measured rates):");
            report.Table(thresholds);
        }
        if (confirmations.Count > 0)
        {
            report.Heading($"The analytic model against the noisy gate engine, {confirmSize}x{confirmSize}", 3);
            report.Text(Lines(
                "The same pipeline without the accuracy budget (the simulator engines run without it) rendered by the noisy gate engine, which",
                "simulates the gate-level oracle's circuit under `runWithNoise` (`--engine gate --noise p`) and cannot be seeded, beside the",
                "analytic engine under the gate-level oracle's model: one render each, so differences of a few pixels are sampling."));
            var table = new TextTable("confirmations", ["scene", "p per gate", "analytic Int/Ray", "gate Int/Ray", "analytic NRMSE", "gate NRMSE", "analytic #Dpix", "gate #Dpix", "gate wall time"]);
            foreach (var c in confirmations)
                table.Row(c.Scene, Rate(c.PerGate), F(c.Analytic.Result.Total.PerRayConservative, "0.00"), F(c.FullState.Result.Total.PerRayConservative, "0.00"),
                    F(c.Analytic.Error.Nrmse * 100, "0.00") + " %", F(c.FullState.Error.Nrmse * 100, "0.00") + " %", I(c.Analytic.Error.DifferentPixels), I(c.FullState.Error.DifferentPixels),
                    F(c.FullState.WallTime.TotalSeconds, "0") + " s");
            report.Table(table);
        }
    }
}
