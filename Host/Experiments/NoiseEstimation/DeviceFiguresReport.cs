using System.Globalization;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Reports;
using static QuantumRayTracing.Experiments.DeviceFigures;

namespace QuantumRayTracing.Experiments;

/// <summary>The sections of docs/noise-estimation.md named after the QCoin paper's figs. 10, 11 and 12, from <see cref="DeviceFigures"/>.</summary>
public static class DeviceFiguresReport
{
    private static string F(double value, string format = "0.00000") => value.ToString(format, CultureInfo.InvariantCulture);

    private static string G(double value) => value.ToString("G3", CultureInfo.InvariantCulture);

    public static void Add(Report report, Figures figures, NoiseEstimationSettings settings)
    {
        FigureTen(report, figures, settings);
        FigureEleven(report, figures);
        FigureTwelve(report, figures);
    }

    private static void FigureTen(Report report, Figures figures, NoiseEstimationSettings settings)
    {
        var (fit, points) = (figures.Fit, figures.FigureTen);
        var device = fit.Device;
        var last = NoiseEstimationSettings.StepBudgets[^1];
        report.Heading("Fig. 10: QCoin at f = ½ on the single-qubit coin under a device model fitted to the paper's device");
        report.Text($"""
            Scope: the paper's fig. 10 circuit (one qubit rotated to the mean, Grover operator Q Z Q⁻¹ Z, eq. 46; `CountDirectCoinHeadsOnDevice`)
            at f = 0.5, k = 0 (MC on the device) and k = 2..7, on the analytic engine under a **device noise model fitted** to the paper's
            two observations, with {settings.Trials} runs per point (the paper: 300). The device model: depolarizing p1 after each one-qubit
            gate (p/3 each of X, Y, Z), none at the measurement, and a readout error that flips a read 0 to 1 with P0 and a 1 to 0 with P1
            (exact on one qubit: [noise.md](noise.md) and the tests `DeviceNoiseSimulatorTests` check it against the noisy simulator).
            This coin has no two-qubit gate.

            **What we read from the paper, and the fit.** The text gives no numbers for its plots, only: (1) on the device, k = 0 follows
            MC up to about {PaperPlateauQueries} queries and then stops falling, put down to readout error; (2) the error stops falling
            beyond k ≈ 5 (k = 6, 7 no better than 5). Depolarizing noise cannot bias an unamplified coin at f = ½, so the plateau is the
            readout's bias |P0 − P1|/2 alone; we set it to MC's error at {PaperPlateauQueries} queries, √(2/π)·½/√{PaperPlateauQueries} =
            {F(fit.PlateauTarget, "0.0000")}, with P0 = {G(AssumedReadZeroAsOne)} assumed (only the difference matters at k = 0), which gives
            P1 = {G(device.ReadOneAsZero)}. With that readout we scanned p1 over {string.Join(", ", FitOneQubitRates.Select(G))} for the k with
            the lowest error at {last:N0} queries ({Math.Max(100, settings.Trials / 4)} runs each) and took the middle rate whose best k is
            {NoiseEstimationReport.PaperStopSteps}: **p1 = {G(device.OneQubit)}** (best k there: {fit.BestSteps}). A fit to two read-off
            features, not a measurement of IBM Q5: one-qubit errors on that device were nearer 1e-3 per native gate, and an Ry there is
            several pulses.
            """);
        var scan = new TextTable("fig10-fit", ["p1", .. Enumerable.Range(0, 8).Select(k => k == 0 ? "k = 0" : $"k = {k}"), "best k"]);
        foreach (var rate in FitOneQubitRates)
        {
            var row = fit.Scan.Where(p => p.OneQubit == rate).OrderBy(p => p.Steps).ToArray();
            scan.Row([G(rate), .. row.Select(p => F(p.Error)), row.MinBy(p => p.Error)!.Steps.ToString(CultureInfo.InvariantCulture)]);
        }
        report.Text($"The fit's scan: mean absolute error at {last:N0} queries, readout P0 = {G(device.ReadZeroAsOne)}, P1 = {G(device.ReadOneAsZero)}.");
        report.Table(scan);

        var table = new TextTable("fig10", ["queries", "MC, noiseless", .. Enumerable.Range(0, 8).Select(k => k == 0 ? "k = 0 (device)" : $"k = {k}")]);
        foreach (var q in NoiseEstimationSettings.StepBudgets)
        {
            string Cell(int k) => points.FirstOrDefault(p => p.Series == "device model" && p.Steps == k && p.Queries == q) is { } p ? F(p.Error) : "–";
            table.Row([q.ToString("N0", CultureInfo.InvariantCulture), F(points.Single(p => p.Series == "MC, noiseless" && p.Queries == q).Error), .. Enumerable.Range(0, 8).Select(Cell)]);
        }
        report.Text($"Fig. 10 at the fitted model ({device.Description()}); mean absolute error, queries counted as a flip 1 and a Grover operator 2.");
        report.Table(table);
        PlotSeries Series(string label, string series, int k) => new(label, [.. points.Where(p => p.Series == series && p.Steps == k).Select(p => ((double)p.Queries, p.Error))]);
        var title = $"p1 = {G(device.OneQubit)}, P0 = {G(device.ReadZeroAsOne)}, P1 = {G(device.ReadOneAsZero)}";
        report.Plot("fig10-left", new PlotSpec($"Fig. 10 left: MC and k = 0 on the device model ({title})", "queries", "mean absolute error", AxisScale.Log10, AxisScale.Log10,
            [Series("MC, noiseless", "MC, noiseless", 0), Series("k = 0, device model", "device model", 0)], 900, 520), "Fig. 10 (left): k = 0 on the fitted device model stops falling at the readout's bias; noiseless MC keeps falling");
        report.Plot("fig10-centre", new PlotSpec($"Fig. 10 centre: k = 0, 2..5 on the device model ({title})", "queries", "mean absolute error", AxisScale.Log10, AxisScale.Log10,
            [.. new[] { 0, 2, 3, 4, 5 }.Select(k => Series($"k = {k}", "device model", k))], 900, 520), "Fig. 10 (centre): k = 2..5 on the fitted device model");
        report.Plot("fig10-right", new PlotSpec($"Fig. 10 right: k = 5, 6, 7 on the device model ({title})", "queries", "mean absolute error", AxisScale.Log10, AxisScale.Log10,
            [.. new[] { 5, 6, 7 }.Select(k => Series($"k = {k}", "device model", k))], 900, 520), "Fig. 10 (right): beyond k = 5 more amplification does not help on the fitted device model");
    }

    private static void FigureEleven(Report report, Figures figures)
    {
        var rows = figures.FigureEleven;
        var device = figures.Fit.Device;
        var (one, two) = DeviceCircuitGates.DirectQss(2);
        report.Heading("Fig. 11: QSS with 7 queries on the three-colour image, on the device model");
        report.Text($"""
            Scope: the paper's device QSS (fig. 9 top: no subpixel register, two counter qubits and the single-qubit coin; t = 2, so
            2^3 − 1 = 7 queries; `MeasureDirectQssOnDevice`: every gate of each Grover operator Q Z Q⁻¹ Z under its counter qubit, the
            inverse QFT and the register reversal by SWAPs, {one} one-qubit and {two} two-qubit gates) on pixels whose colours are only 0, 0.5
            and 1, as in the paper (our image: the three colours in equal shares, one estimate per pixel; the
            paper's layout is not in its text). Noiseless, 7 queries read these colours exactly. The device model is fig. 10's fit (p1 =
            {G(device.OneQubit)}, readout P0 = {G(device.ReadZeroAsOne)}, P1 = {G(device.ReadOneAsZero)}) with two-qubit noise p2 per qubit swept;
            p2 = 0.0253 makes a two-qubit gate fail with probability 1 − (1 − p2)² = 5 %, the paper's "almost 5 %". Global depolarizing
            weight over the gates (s = 2/3), readout exact; checked against the noisy simulator in `DeviceNoiseSimulatorTests`. The paper
            reports the mean absolute error up by 0.30 on IBM Q5; QCoin at fig. 1's setting (240 queries, k = 3) beside it, as in the paper's
            right-hand images.
            """);
        var table = new TextTable("fig11", ["estimator", "queries", "noise", "p2 per qubit", "two-qubit gate error", "mean absolute error", "rise over noiseless", "exact pixels"]);
        foreach (var row in rows)
        {
            var baseline = rows.First(r => r.Method == row.Method && r.Label == "noiseless").Error;
            table.Row(row.Method, row.Queries.ToString(CultureInfo.InvariantCulture), row.Label, G(row.TwoQubit), $"{F(1 - Math.Pow(1 - row.TwoQubit, 2) , "0.0%")}",
                F(row.Error, "0.000"), F(row.Error - baseline, "+0.000;-0.000;0.000"), F(row.ExactShare, "0.0%"));
        }
        report.Table(table);
        var fivePercent = rows.Single(r => r.Method.StartsWith("qss", StringComparison.Ordinal) && r.TwoQubit == 0.0253);
        report.Text($"""
            At a 5 % two-qubit gate error the model puts QSS's error up by {F(fivePercent.Error - rows[0].Error, "0.00")} (the paper: 0.30 on the
            device), of which the readout alone gives {F(rows[1].Error - rows[0].Error, "0.00")}. QCoin on the single-qubit coin has no two-qubit gate.
            """);
    }

    private static void FigureTwelve(Report report, Figures figures)
    {
        report.Heading("Fig. 12: additional register qubits and amplitude amplification iterations against the error ε, without noise");
        report.Text($"""
            Scope: the paper's fig. 12 (sec. 7) relates, for an error ε, the additional register qubits (left) and the amplitude
            amplification iterations in one circuit (right) of QSS and QCoin; no noise. QSS needs t counter qubits beyond the log N
            subpixel qubits and runs 2^t − 1 Grover operators in one coherent circuit; t here is the smallest whose exact mean absolute
            error over means uniform on [0, 1] (estimate sin²(πy/2^t), from the readout distribution) is at most ε. QCoin needs no
            register beyond the subpixel qubits and the coin; its deepest circuit is step k's flip, 2^(k−1) operators; k here is the
            smallest whose measured mean absolute error (analytic engine, noiseless, {FigureTwelveFlips} flips per step, uniform random means) is at most ε.
            The queries columns say what each spends for one estimate: QSS one run, QCoin {FigureTwelveFlips} flips per step (so its
            k = 1 row already holds many queries; a smaller QCoin budget needs more steps for the same ε).
            """);
        var table = new TextTable("fig12", ["ε", "QSS: extra register qubits t", "QSS: iterations per circuit", "QSS: queries", "QSS error", "QCoin: extra register qubits", "QCoin: steps k", "QCoin: iterations in its deepest circuit", "QCoin: queries", "QCoin error"]);
        string Count(long value) => value.ToString("N0", CultureInfo.InvariantCulture);
        foreach (var row in figures.FigureTwelve)
            table.Row(G(row.Target), row.QssQubits > 0 ? row.QssQubits.ToString(CultureInfo.InvariantCulture) : "> 12", row.QssQubits > 0 ? Count(row.QssIterations) : "–",
                row.QssQubits > 0 ? Count(QssRequest.QueriesPerRun(row.QssQubits)) : "–", row.QssQubits > 0 ? F(row.QssError) : "–", "0",
                row.QCoinSteps > 0 ? row.QCoinSteps.ToString(CultureInfo.InvariantCulture) : "> 10", row.QCoinSteps > 0 ? Count(row.QCoinIterations) : "–",
                row.QCoinSteps > 0 ? Count(FigureTwelveFlips * QCoinEstimator.MinimumQueries(row.QCoinSteps)) : "–", row.QCoinSteps > 0 ? F(row.QCoinError) : "–");
        report.Table(table);
        var rows = figures.FigureTwelve.Where(r => r.QssQubits > 0).ToArray();
        report.Plot("fig12", new PlotSpec("Fig. 12: register qubits and iterations per circuit against ε (no noise)", "error ε", "count", AxisScale.Log10, AxisScale.Log10,
            [
                new PlotSeries("QSS: extra register qubits", [.. rows.Select(r => (r.Target, (double)r.QssQubits))]),
                new PlotSeries("QSS: iterations per circuit", [.. rows.Select(r => (r.Target, (double)r.QssIterations))]),
                new PlotSeries("QCoin: iterations in its deepest circuit", [.. figures.FigureTwelve.Where(r => r.QCoinSteps > 0).Select(r => (r.Target, (double)r.QCoinIterations))]),
            ], 900, 520), "Fig. 12: QSS's register and coherent iterations grow as ε falls; QCoin adds no register qubit (not drawn on the log axis)");
    }
}
