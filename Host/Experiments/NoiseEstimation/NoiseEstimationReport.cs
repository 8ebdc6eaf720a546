using System.Globalization;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using static QuantumRayTracing.Experiments.NoiseEstimationExperiment;

namespace QuantumRayTracing.Experiments;

/// <summary>docs/noise-estimation.md from what <see cref="NoiseEstimationExperiment"/> measured.</summary>
public static class NoiseEstimationReport
{
    public const string Title = "Mean estimation under hardware noise";

    /// <summary>The QCoin paper's fig. 10: beyond k ≈ 5 (about 16 amplitude amplifications) the device's error stopped falling.</summary>
    public const int PaperStopSteps = 5;

    public static Report Build(Result result, NoiseEstimationSettings settings, string machine)
    {
        var report = new Report(Title);
        report.Text($"""
            The QCoin paper's device experiments of sec. 6 and its fig. 12 (sec. 7): the sections named "Fig. 10", "Fig. 11" and "Fig. 12"
            reproduce those figures as the paper has them (fig. 10 and fig. 11 on a device noise model fitted to the paper, fig. 12
            without noise; each states its scope). Then our own studies under symmetric Pauli noise, named as ours: QCoin's best k against
            the per-gate error (our counterpart of fig. 10), QSS against QCoin, MLAE and the noisy mean coin at equal queries, the QCoin
            image under noise (our counterpart of fig. 1 right), and a maximum-likelihood estimator built for noise. Every figure comes
            from the analytic supersampling engine, seeded (seed {settings.Seed}).

            **Noise model of our own studies.** Depolarizing Pauli noise p per gate and qubit (p/3 each of X, Y, Z after every gate and before every measurement, on
            each qubit it touches: `--noise p`), as the QDK's noisy simulator applies it. The analytic engine turns it into a fidelity: a flip
            after m Grover operators is ideal with probability Φ = F₀ · F^m and otherwise reads its maximally mixed register (a head with
            probability ½ on the mean and direct coins), F = (1 − p)^(s·L) per Grover operator and F₀ likewise for the preparation and
            measurement, L the circuit's noise locations (one per qubit per gate, counted in closed form by `CoinNoiseLocations`) and s = 2/3
            (the single-qubit direct coin is modelled exactly: one qubit's depolarizing channel per location, Φ = (1 − 4p/3)^L); a QSS readout is the ideal distribution mixed towards uniform by its run's Φ. The model is checked against the noisy simulator in
            [noise.md](noise.md) (`qrt bench noise --parts supersampling`).

            **Counting convention** ([conventions.md](conventions.md)): queries count the oracle and its inverse, so a coin flip costs 1, a flip
            after m Grover operators 1 + 2m and a QSS run with t counter bits 2^(t+1) − 1; Monte Carlo with Q queries takes Q samples. MC in
            the noisy tables is the quantum coin's unamplified flips (`-m mc`) on the same noisy engine, labelled the noisy mean coin;
            classical MC, where shown, is noiseless. Error:
            the mean absolute error of the estimated mean over {settings.Trials} runs or pixels per point (fig. 1: over the image's pixels and
            channels, in 8-bit levels). Measured in {result.Elapsed.TotalMinutes:0.0} min on the machine named at the end.
            """);
        DeviceFiguresReport.Add(report, result.Device, settings);
        Steps(report, result, settings);
        Nisq(report, result);
        Image(report, result, settings);
        Aware(report, result);
        return report;
    }

    private static string F(double value, string format = "0.00000") => value.ToString(format, CultureInfo.InvariantCulture);

    private static string Rate(double p) => p == 0 ? "0" : p.ToString("0.#e0", CultureInfo.InvariantCulture);

    /// <summary>The k with the lowest error at the largest budget, for one coin and rate.</summary>
    public static int BestSteps(IEnumerable<StepsPoint> points, string coin, double rate)
    {
        var last = points.Where(p => p.Coin == coin && p.Rate == rate).Max(p => p.Queries);
        return points.Where(p => p.Coin == coin && p.Rate == rate && p.Queries == last).MinBy(p => p.Error)!.Steps;
    }

    private static void Steps(Report report, Result result, NoiseEstimationSettings settings)
    {
        var points = result.Steps;
        var last = NoiseEstimationSettings.StepBudgets[^1];
        var direct = CoinNoiseLocations.GroverOperator(CoinKind.Direct, [0.5]);
        var full = CoinNoiseLocations.GroverOperator(CoinKind.Shifted, FullCoinValues.Select(v => v - 0.25).ToArray());
        report.Heading("QCoin at f = ½ against the number of steps k under Pauli noise (our counterpart of the QCoin paper's fig. 10, not a reproduction)");
        report.Text($"""
            QCoin (Algorithm 1) at f = 0.50 with k = 1..7 shift-and-scale steps (step i flips its coin after 2^(i−1) Grover operators, so
            k = 5 reaches 16) and k = 0 (MC: the coin's unamplified flips, under the same noise), {settings.Trials} runs per point, on two coins: the paper's hardware coin, one qubit
            rotated straight to the head amplitude the host computes (`DirectCoinEngine`: {direct} noise locations per Grover operator, A Z A† Z),
            and our full subpixel coin over 8x8 = 64 subpixels of values i/63 (the shifted coin's Grover operator: {full:N0} locations,
            the shader oracle's multiply controlled rotations). The table gives the error at {last:N0} queries and the k with the lowest error
            there: the k beyond which more amplification stops helping.
            """);
        var table = new TextTable("steps", ["coin", "p", "F per Grover operator", .. Enumerable.Range(0, 8).Select(k => k == 0 ? "k = 0 (MC, noisy coin)" : $"k = {k}"), "best k"]);
        foreach (var coin in new[] { "direct", "full 8x8" })
            foreach (var rate in NoiseEstimationSettings.StepRates)
            {
                var values = coin == "direct" ? new[] { 0.5 } : FullCoinValues.Select(v => v - 0.25).ToArray();
                var kind = coin == "direct" ? CoinKind.Direct : CoinKind.Shifted;
                var fidelity = rate == 0 ? 1 : SupersamplingNoise.GroverOperatorFidelity(kind, values, NoiseModel.Depolarizing(rate));
                var row = Enumerable.Range(0, 8).Select(k => points.FirstOrDefault(p => p.Coin == coin && p.Rate == rate && p.Steps == k && p.Queries == last) is { } point ? F(point.Error) : "–");
                table.Row([coin, Rate(rate), F(fidelity, "0.0000"), .. row, BestSteps(points, coin, rate).ToString(CultureInfo.InvariantCulture)]);
            }
        report.Table(table);

        var matching = NoiseEstimationSettings.StepRates.Where(r => BestSteps(points, "direct", r) == PaperStopSteps).ToArray();
        var deviceBest = BestSteps(points, "direct", settings.DeviceRate);
        report.Text($"""
            **The device's noise level, a fit.** The paper gives no error rates for its runs beyond "multi-qubit gate errors are almost 5%" and
            readout error; its QCoin circuit is single-qubit (the direct coin), and on the device the error stopped falling beyond k ≈ {PaperStopSteps}.
            So the rate standing in for the device is a one-parameter fit to that one observation, the rate at which the simulated direct coin
            does the same: here the best k is {PaperStopSteps} at p = {(matching.Length == 0 ? "none of the rates swept" : string.Join(", ", matching.Select(Rate)))}; we use p = {Rate(settings.DeviceRate)}
            (best k there: {deviceBest}), which gives the direct coin F = {F(SupersamplingNoise.GroverOperatorFidelity(CoinKind.Direct, [0.5], NoiseModel.Depolarizing(settings.DeviceRate)), "0.000")}
            per Grover operator, so after the 16 operators of k = 5 about {F(Math.Pow(SupersamplingNoise.GroverOperatorFidelity(CoinKind.Direct, [0.5], NoiseModel.Depolarizing(settings.DeviceRate)), 16), "0.00")}
            of each flip survives. Single-qubit gate errors on IBM's five-qubit devices of the time were of the order of 1e-3, but an Ry there
            is several native pulses. The fit matches the best k only. In fig. 10 (left) k = 0 also stops improving on the device, which the
            paper puts down to readout error; a symmetric depolarizing model cannot show that, as it leaves a k = 0 coin at f = ½ unbiased
            (the k = 0 column above does not grow with p): its error before a measurement is symmetric, and a readout error that favours
            one outcome, which can bias that coin, is not in it. The full coin needs about
            {F((double)full / direct, "0")} times as many locations per operator, so it gives up amplification at a rate that many times lower.
            """);
        report.Plot("steps-direct", new PlotSpec($"QCoin at f = 0.5, direct coin, depolarizing p = {Rate(settings.DeviceRate)} per gate",
                "queries (flip 1, Grover operator 2)", "mean absolute error", AxisScale.Log10, AxisScale.Log10,
                [.. Enumerable.Range(0, 8).Select(k => new PlotSeries(k == 0 ? "k = 0 (MC)" : $"k = {k}",
                    [.. points.Where(p => p.Coin == "direct" && p.Rate == settings.DeviceRate && p.Steps == k).Select(p => ((double)p.Queries, p.Error))]))], 1000, 560),
            "QCoin error against queries for each k on the direct coin at the rate fitted to the device");
        report.Plot("steps-best", new PlotSpec("Best QCoin k at 10,000 queries against the per-gate error (f = 0.5)", "per-gate error p", "best k",
                AxisScale.Log10, AxisScale.Linear,
                [
                    .. new[] { "direct", "full 8x8" }.Select(coin => new PlotSeries($"{coin} coin",
                        [.. NoiseEstimationSettings.StepRates.Where(r => r > 0).Select(r => (r, (double)BestSteps(points, coin, r)))])),
                    new PlotSeries($"the paper's device: k = {PaperStopSteps}", [(NoiseEstimationSettings.StepRates.Where(r => r > 0).Min(), PaperStopSteps), (NoiseEstimationSettings.StepRates.Max(), PaperStopSteps)], Markers: false),
                ], 1000, 520),
            "The k beyond which amplification stops helping, against the per-gate error, for both coins");
    }

    /// <summary>
    /// The per-gate error from which on <paramref name="method"/>'s error stays at or above Monte Carlo's at the same budget
    /// (interpolated in log p at the last crossing); null where it is still below MC at the highest rate, 0 where it never is below.
    /// </summary>
    public static double? FallbackRate(IReadOnlyList<MethodPoint> points, string method, long queries)
    {
        var rates = points.Select(p => p.Rate).Distinct().Order().ToArray();
        double Gap(double rate) => points.Single(p => p.Rate == rate && p.Queries == queries && p.Method == method).Error
            - points.Single(p => p.Rate == rate && p.Queries == queries && p.Method == "MC").Error;
        if (Gap(rates[^1]) < 0) return null;
        var first = rates.Length - 1;
        while (first > 0 && Gap(rates[first - 1]) >= 0) first--;
        if (first == 0) return 0;
        var (below, above) = (rates[first - 1], rates[first]);
        if (below == 0) return above;
        var share = -Gap(below) / (Gap(above) - Gap(below));
        return Math.Exp(Math.Log(below) + share * (Math.Log(above) - Math.Log(below)));
    }

    /// <summary>How the noisy tables label the MC estimator: the quantum mean coin's unamplified flips on the noisy engine.</summary>
    private static string Label(string method) => method switch
    {
        "MC" => "noisy mean coin (MC flips)",
        ClassicalMonteCarlo => "classical MC (noiseless)",
        _ => method,
    };

    private static void Nisq(Report report, Result result)
    {
        var points = result.Nisq;
        var budgets = points.Select(p => p.Queries).Distinct().Order().ToArray();
        var methods = new[] { "MC", "QSS", "QCoin", "MLAE", "MLAE-noise" };
        var amplitudes = Enumerable.Repeat(Math.Sqrt(0.5), NoiseEstimationSettings.NisqSubpixels).ToArray();
        report.Heading("QSS against QCoin, MLAE and the noisy mean coin at equal queries, under noise");
        report.Text($"""
            Our own comparison, for the paper's claim that QCoin suits noisy devices better than QSS; it is not a figure of the paper
            (the paper's figs. 11 and 12 are reproduced in their own sections above).
            Pixels of {NoiseEstimationSettings.NisqSubpixels} subpixels (4x4) with independent uniform random values, one estimate per pixel, at the budgets of
            QSS with t = {string.Join(", ", NoiseEstimationSettings.NisqCounterBits)} counter bits ({string.Join(", ", budgets)} queries), each estimator at the same queries:
            MC (the mean coin's unamplified flips under the same noise), QSS for continuous values (estimate sin²(πy/2^t)), QCoin with the measured best k for the budget, plain MLAE and the
            noise-aware MLAE with the default K. Each circuit carries its own noise: its locations are counted from its own gates, so a QSS
            run (t counter qubits, every Grover operator controlled by one of them, the inverse QFT) meets far more noise than a QCoin or MLAE
            flip of the same queries, whose circuits hold only the subpixel register and the coin.
            """);
        var sizes = new TextTable("nisq-locations", ["circuit (16 subpixels)", "noise locations", "Φ at p = 1e-4", "Φ at p = 1e-3"]);
        string Phi(long locations, double p) => F(DepolarizingApproximation.Default.Fidelity(NoiseModel.Depolarizing(p), locations), "0.000");
        (string Name, long Locations)[] circuits =
        [
            ("mean coin: a flip (m = 0)", CoinNoiseLocations.Flip(CoinKind.Mean, amplitudes, 0)),
            ("mean coin: one Grover operator", CoinNoiseLocations.GroverOperator(CoinKind.Mean, amplitudes)),
            ("shifted coin (QCoin): one Grover operator", CoinNoiseLocations.GroverOperator(CoinKind.Shifted, amplitudes)),
            .. NoiseEstimationSettings.NisqCounterBits.Select(t => ($"QSS run, t = {t} ({(1 << t) - 1} controlled operators)", CoinNoiseLocations.Qss(amplitudes, t))),
        ];
        foreach (var (name, locations) in circuits)
            sizes.Row(name, locations.ToString("N0", CultureInfo.InvariantCulture), Phi(locations, 1e-4), Phi(locations, 1e-3));
        report.Table(sizes);

        string[] columns = [ClassicalMonteCarlo, .. methods, AlwaysHalf];
        report.Text($"""
            Baselines: classical MC is Monte Carlo with as many samples as queries on a noiseless machine (the classical computer's
            estimator); the noisy mean coin is the quantum coin's unamplified flips under the same noise as the quantum estimators (MC
            run on the device); "{AlwaysHalf}" answers ½ for every pixel without a query, the floor every estimator must beat.
            """);
        var table = new TextTable("nisq", ["p", "queries", .. columns.Select(Label), "QSS / QCoin"]);
        foreach (var rate in NoiseEstimationSettings.NisqRates)
            foreach (var q in budgets)
            {
                double Error(string m) => points.Single(p => p.Rate == rate && p.Queries == q && p.Method == m).Error;
                table.Row([Rate(rate), q.ToString(CultureInfo.InvariantCulture), .. columns.Select(m => F(Error(m))), F(Error("QSS") / Error("QCoin"), "0.00")]);
            }
        report.Table(table);
        var floor = points.First(p => p.Method == AlwaysHalf).Error;
        string Beating(double rate) => string.Join(", ", budgets.Select(q =>
            $"{q}: {string.Join(", ", methods.Where(m => points.Single(p => p.Rate == rate && p.Queries == q && p.Method == m).Error < floor).Select(Label).DefaultIfEmpty("none"))}"));
        report.Text($"""
            **Against always answering ½** ({F(floor, "0.000")} on these pixels, whose means cluster near ½): the estimators below it at each
            budget (queries: estimators) without noise are {Beating(0)}; at p = {Rate(NoiseEstimationSettings.NisqRates[^1])}: {Beating(NoiseEstimationSettings.NisqRates[^1])}.
            Classical MC without noise beats it from {budgets.Where(q => points.Single(p => p.Rate == 0 && p.Queries == q && p.Method == ClassicalMonteCarlo).Error < floor).Select(q => q.ToString(CultureInfo.InvariantCulture)).DefaultIfEmpty("none of the budgets").First()} queries on.
            """);

        var fallback = new TextTable("nisq-fallback", ["queries", .. methods.Skip(1)]);
        foreach (var q in budgets)
            fallback.Row([q.ToString(CultureInfo.InvariantCulture), .. methods.Skip(1).Select(m => FallbackRate(points, m, q) switch
            {
                null => $"> {Rate(NoiseEstimationSettings.NisqRates[^1])}",
                0 => "never below MC",
                { } r => Rate(r),
            })]);
        report.Text("**Where each quantum estimator falls to the noisy mean coin's error**: the per-gate error from which on its error stays at or above MC's at the same queries (interpolated in log p between the rates swept; at the smallest budgets the quantum estimators have too few flips to beat MC even without noise).");
        report.Table(fallback);

        double Ratio(double rate, long q) =>
            points.Single(p => p.Rate == rate && p.Queries == q && p.Method == "QSS").Error / points.Single(p => p.Rate == rate && p.Queries == q && p.Method == "QCoin").Error;
        var byRate = new TextTable("nisq-qss-qcoin", ["p", .. budgets.Select(q => $"QSS / QCoin at {q}"), "budgets where QCoin is ahead", $"best estimator at {budgets[^1]} queries"]);
        foreach (var rate in NoiseEstimationSettings.NisqRates)
        {
            var best = points.Where(p => p.Rate == rate && p.Queries == budgets[^1] && methods.Contains(p.Method)).MinBy(p => p.Error)!;
            byRate.Row([Rate(rate), .. budgets.Select(q => F(Ratio(rate, q), "0.00")), $"{budgets.Count(q => Ratio(rate, q) > 1)} of {budgets.Length}", $"{best.Method} ({F(best.Error)})"]);
        }
        report.Text("""
            **Does "QCoin beats QSS on NISQ" hold here?** QSS's error over QCoin's at equal queries, by per-gate error (above 1: QCoin is
            ahead), and which estimator errs least at the largest budget:
            """);
        report.Table(byRate);
        var median = NoiseEstimationSettings.NisqRates.ToDictionary(r => r, r => budgets.Select(q => Ratio(r, q)).Order().ElementAt(budgets.Length / 2));
        var wins = median.Where(m => m.Key > 0 && m.Value > 1).Select(m => m.Key).ToArray();
        var losses = median.Where(m => m.Key > 0 && m.Value <= 1).Select(m => m.Key).ToArray();
        double ErrorOf(double rate, long q, string method) => points.Single(p => p.Rate == rate && p.Queries == q && p.Method == method).Error;
        // A lead counts where QCoin still errs less than MC at some budget; elsewhere both have lost to the unamplified coin.
        var real = wins.Where(r => budgets.Any(q => ErrorOf(r, q, "QCoin") < ErrorOf(r, q, "MC"))).ToArray();
        var empty = wins.Except(real).ToArray();
        string Rates(IEnumerable<double> rates) => string.Join(", ", rates.Select(Rate));
        string Range(double[] rates, string method)
        {
            var errors = rates.SelectMany(r => budgets.Skip(1).Select(q => ErrorOf(r, q, method))).ToArray();
            return $"{F(errors.Min(), "0.00")} to {F(errors.Max(), "0.00")}";
        }
        var half = points.First(p => p.Method == AlwaysHalf).Error;
        var bothWorse = empty.Length > 0 && empty.All(r => budgets.Skip(1).All(q => ErrorOf(r, q, "QSS") > half && ErrorOf(r, q, "QCoin") > half));
        report.Text($"""
            In short: QCoin beats QSS (the median ratio over the budgets above 1) at p = {(wins.Length == 0 ? "none of the rates" : Rates(wins))};
            without noise the median is {F(median[0], "0.00")}. {(real.Length == 0 ? "" : $"Where QCoin still errs less than MC at some budget, p = {Rates(real)}, it leads by {F(real.Min(r => median[r]), "0.0")}x to {F(real.Max(r => median[r]), "0.0")}x in the median and up to {F(real.Max(r => budgets.Max(q => Ratio(r, q))), "0.0")}x at the largest budgets.")}
            {(empty.Length == 0 ? "" : $"At p = {Rates(empty)} QCoin errs more than MC at every budget, and from {budgets[1]} queries on QSS errs {Range(empty, "QSS")} (about what a uniform readout gives) and QCoin {Range(empty, "QCoin")}{(bothWorse ? $": both worse than always answering ½ ({F(half, "0.000")} on these pixels)" : "")}.")}
            {(losses.Length == 0 ? "" : $"At p = {Rates(losses)} QSS errs less than QCoin, but there both have fallen to MC's error or worse (table above): QCoin's shifted coin then reads heads at the mixed register's rate and its steps pull the estimate off, while QSS's flattened readout only spreads it.")}
            So the paper's conclusion holds here {(real.Length == 0 ? "at none of the rates swept" : $"up to p = {Rate(real.Max())}")}, for the reason the paper gave: QSS's far
            larger circuit (the locations above). It does not make QCoin the estimator to use: the rates where each estimator falls to MC's
            error are in the table above, and the last column names the estimator that errs least.
            """);
        foreach (var q in new[] { budgets[^1], budgets[budgets.Length / 2] })
            report.Plot($"nisq-{q}", new PlotSpec($"Error at {q} queries against depolarizing p per gate (16 subpixels)", "per-gate error p (0 drawn at 1e-6)", "mean absolute error",
                    AxisScale.Log10, AxisScale.Log10,
                    [.. methods.Select(m => new PlotSeries(m, [.. points.Where(p => p.Queries == q && p.Method == m).Select(p => (p.Rate == 0 ? 1e-6 : p.Rate, p.Error))]))], 1000, 540),
                $"Mean absolute error at {q} queries against the per-gate error (MC: the noisy mean coin)");
    }

    private static void Image(Report report, Result result, NoiseEstimationSettings settings)
    {
        var input = result.ImageInput;
        report.Heading("QCoin supersampling under Pauli noise (our counterpart of the QCoin paper's fig. 1 right, a device image)");
        report.Text($"""
            The built-in Qornell box rendered classically at {input.Image.Width}x{input.Image.Height}, each {input.Width}x{input.Height} output pixel the
            mean of 8x8 = 64 subpixels per channel, 240 queries per pixel and channel, QCoin with k = 3 (the paper's fig. 1 choice). The
            paper's device image used the direct coin (the host computes each pixel's value; the device only amplifies); we show it at the
            rate fitted to the device, p = {Rate(settings.DeviceRate)}, and the full 8x8 subpixel coin at the lowest rate swept, p = {Rate(NoiseEstimationSettings.StepRates.Where(r => r > 0).Min())}
            (its Grover operator has about 1,500 times the direct coin's noise locations). Error against the exact average in 8-bit levels.
            """);
        var table = new TextTable("fig1", ["run", "mean abs error (levels)", "exact pixels"]);
        foreach (var run in result.Images)
            table.Row(run.Label, F(run.Error.MeanLevels, "0.00"), F(100 * run.Error.ExactShare, "0.0") + "%");
        report.Table(table);
        var (w, h) = (input.Width, input.Height);
        report.Image("fig1", ImageMontage.Grid(
            [
                [(input.Ideal(), "ideal"), .. result.Images.Select(r => (r.Result.Image, Short(r.Label)))],
                [(input.Ideal(), "ideal"), .. result.Images.Select(r => (SupersamplingImageBenchmark.ErrorMap(r.Error, w, h, 8), "error x8"))],
            ], 3),
            "Top: the ideal image and each estimate; bottom: each absolute error times 8");
    }

    private static string Short(string label) => label.Replace(", noiseless", "").Replace(", direct coin", " direct").Replace(", full coin", " full");

    private static void Aware(Report report, Result result)
    {
        var methods = new[] { "MC", "QCoin", "MLAE", "MLAE-noise" };
        var budgets = NoiseEstimationSettings.AwareBudgets;
        report.Heading("A noise-aware estimator: MLAE with a fitted depolarizing decay");
        report.Text("""
            `supersample -m mlae-noise` (`NoiseAwareMaximumLikelihoodEstimator`, after Tanaka et al. 2021, "Amplitude estimation via maximum
            likelihood on noisy quantum computer") reads MLAE's flips with the depolarized coin's likelihood,
            P(head) = Φ · sin²((2m+1)θ) + (1 − Φ)/2 with Φ = e^(−γ(m+½)), and fits the decay γ per Grover operator together with θ (a grid over
            θ and γ, then golden-section refinement), under a prior e^(−10γ) on the decay (an exponential of mean 0.1: without it a chance
            fit of a large decay on a noiseless machine lets θ follow the few unamplified flips alone, just off f = ½). It keeps the decay
            only when it raises the log-likelihood, prior counted, by more than 5.41/2 (a likelihood-ratio test at 1% on a noiseless
            machine) and the fitted mean is not anomalous (below), and otherwise reads the flips exactly as plain MLAE.
            Its schedule is adaptive: it first flips the shallow levels of plain MLAE's schedule (the longest prefix within half the
            budget), fits θ and γ to them, and then spends the rest on plain MLAE's remaining levels if it found no decay, or else on the
            one level whose flips lower the Cramér–Rao error of the mean most at the fitted θ and γ (near 2m+1 = 1/γ, where a level's
            information per query k·e^(−γk) peaks) instead of deep levels the noise has flattened; the estimate is the fit to all flips,
            and every estimate spends exactly its budget. The column "predicted (fixed schedule)" is the Fisher information's error for plain MLAE's fixed
            schedule with γ fitted (`MlaeFisherInformation`: √(2/π) σ with σ the Cramér–Rao bound on sin²θ, averaged over uniform
            means): the saturation level of the fixed schedule, which the adaptive one is meant to get under. Inputs: uniform random
            means on the direct coin, whose Grover operator has 4 noise locations, at the per-gate error that gives each decay γ
            (F = e^(−γ) per operator), MC that coin's unamplified flips under the same noise; each estimator draws its flips from its own seeded stream, so two columns differ by sampling
            error too (the targets below give its size).
            """);
        foreach (var sweep in result.Aware)
        {
            var table = new TextTable($"aware-{F(sweep.Decay, "0.###")}", ["queries", .. methods.Select(m => m == "MC" ? "MC (noisy direct coin)" : m), "MLAE-noise predicted (fixed schedule)", "MLAE / MLAE-noise"]);
            foreach (var q in budgets)
            {
                double Error(string m) => sweep.Points.Single(p => p.Queries == q && p.Method == m).Error;
                table.Row([q.ToString(CultureInfo.InvariantCulture), .. methods.Select(m => F(Error(m))), F(Predicted(sweep.Decay, q)), F(Error("MLAE") / Error("MLAE-noise"), "0.00")]);
            }
            report.Text($"**γ = {F(sweep.Decay, "0.###")}** per Grover operator (F = {F(Math.Exp(-sweep.Decay), "0.000")}; depolarizing p = {Rate(sweep.Rate)} per gate on the direct coin):");
            report.Table(table);
        }
        foreach (var sweep in result.Aware.Where(s => s.Decay > 0))
            report.Plot($"aware-{F(sweep.Decay, "0.###")}", new PlotSpec($"Direct coin, γ = {F(sweep.Decay, "0.###")} per Grover operator (p = {Rate(sweep.Rate)} per gate)",
                    "queries", "mean absolute error", AxisScale.Log10, AxisScale.Log10,
                    [
                        .. methods.Select(m => new PlotSeries(m, [.. sweep.Points.Where(p => p.Method == m).Select(p => ((double)p.Queries, p.Error))])),
                        new PlotSeries("MLAE-noise, predicted (fixed schedule)", [.. budgets.Select(q => ((double)q, Predicted(sweep.Decay, q)))], Markers: false),
                    ], 1000, 540),
                $"MC, QCoin, plain and noise-aware MLAE against queries at γ = {F(sweep.Decay, "0.###")}, with the error the Fisher information predicts");

        Targets(report, result);

        var chosen = result.Aware.Where(s => s.Decay > 0).OrderBy(s => Math.Abs(s.Decay - 0.03)).First();
        var last = budgets[^1];
        var levels = Levels(last);
        var anomalous = MlaeFisherInformation.AnomalousMeans(chosen.Decay, levels);
        var bins = Enumerable.Range(0, 40).Select(b => (Low: b / 40.0, High: (b + 1) / 40.0)).ToArray();
        IReadOnlyList<(double, double)> Binned(Func<(double Mean, double Plain, double Aware), double> error) =>
            [.. bins.Select(b => (b, chosen.ByMean.Where(e => e.Mean >= b.Low && e.Mean < b.High).ToArray()))
                .Where(x => x.Item2.Length > 0).Select(x => ((x.b.Low + x.b.High) / 2, x.Item2.Average(error)))];
        report.Plot("aware-by-mean", new PlotSpec($"Error against the mean, {last} queries, γ = {F(chosen.Decay, "0.###")} (bins of 0.025)",
                "mean f", "mean absolute error", AxisScale.Linear, AxisScale.Log10,
                [
                    new PlotSeries("MLAE, measured", Binned(e => e.Plain)),
                    new PlotSeries("MLAE-noise, measured", Binned(e => e.Aware)),
                    new PlotSeries("MLAE-noise, predicted (fixed schedule)", [.. Enumerable.Range(1, 399).Select(c => c / 400.0).Select(f => (f, MlaeFisherInformation.MeanAbsoluteError(f, chosen.Decay, levels)))], Markers: false),
                    new PlotSeries("anomalous means", [.. anomalous.Select(f => (f, MlaeFisherInformation.MeanAbsoluteError(f, chosen.Decay, levels)))], Lines: false),
                ], 1100, 560),
            "Error against the mean, measured and predicted, with the anomalous means marked");
        var anomalies = new TextTable("anomalous-means", ["γ", $"anomalous means at {last} queries (fitting γ costs over 1.5x in σ there)"]);
        foreach (var sweep in result.Aware.Where(s => s.Decay > 0))
            anomalies.Row(F(sweep.Decay, "0.###"), string.Join(", ", MlaeFisherInformation.AnomalousMeans(sweep.Decay, levels).Select(f => F(f, "0.000"))));
        report.Text("""
            **Anomalous means.** Where θ is a simple fraction of π the levels' fringes sit at a few phases, a change of θ and a change of γ
            move every level's head probability alike, and fitting the decay eats the information about the mean: at f = ½ (θ = π/4) every
            level reads ½ whatever the noise. `MlaeFisherInformation.AnomalousMeans` lists the local maxima of σ(γ fitted) / σ(γ known)
            above 1.5; the plot above marks them on the predicted curve.
            """);
        report.Table(anomalies);
    }

    private static (int Iterations, int Flips)[] Levels(long queries)
    {
        var mlae = new MaximumLikelihoodEstimator(queries, MaximumLikelihoodEstimator.DefaultLevels(queries));
        return MlaeFisherInformation.Levels(mlae.Iterations, mlae.Flips);
    }

    /// <summary>The mean absolute error the Fisher information predicts for the noise-aware MLAE at decay γ and a budget.</summary>
    public static double Predicted(double decay, long queries) => MlaeFisherInformation.AverageMeanAbsoluteError(decay, Levels(queries), cells: 400);

    private static void Targets(Report report, Result result)
    {
        var budgets = NoiseEstimationSettings.AwareBudgets;
        var (last, before) = (budgets[^1], budgets[^2]);
        double Error(AwareSweep s, long q, string m) => s.Points.Single(p => p.Queries == q && p.Method == m).Error;
        double Spread(AwareSweep s, long q, string m) => s.Points.Single(p => p.Queries == q && p.Method == m).StandardError;
        var lines = new List<string>();
        foreach (var sweep in result.Aware)
        {
            var label = $"γ = {F(sweep.Decay, "0.###")}";
            if (sweep.Decay == 0)
            {
                var change = budgets.Select(q => Error(sweep, q, "MLAE-noise") / Error(sweep, q, "MLAE") - 1).ToArray();
                // The standard error of each ratio from the two independent means' standard errors (first order).
                var spread = budgets.Select(q => Error(sweep, q, "MLAE-noise") / Error(sweep, q, "MLAE") *
                    Math.Sqrt(Math.Pow(Spread(sweep, q, "MLAE-noise") / Error(sweep, q, "MLAE-noise"), 2) + Math.Pow(Spread(sweep, q, "MLAE") / Error(sweep, q, "MLAE"), 2))).ToArray();
                lines.Add($"- {label}: the noise-aware error against plain MLAE's, budget by budget: {string.Join(", ", change.Select(c => F(100 * c, "+0;-0;0") + "%"))} " +
                    $"(target: within 10%): **{(change.All(c => Math.Abs(c) <= 0.10) ? "met" : change.All(c => c <= 0.10) ? "met where it is worse, and it is better by more than 10% somewhere" : "not met")}**; " +
                    $"one standard error of each ratio (sampling): {string.Join(", ", spread.Select(e => F(100 * e, "0") + "%"))}.");
                continue;
            }
            var saturated = Error(sweep, last, "MLAE") >= 0.9 * Error(sweep, before, "MLAE");
            var ratio = Error(sweep, last, "MLAE") / Error(sweep, last, "MLAE-noise");
            var worse = budgets.Where(q => Error(sweep, q, "MLAE-noise") > Error(sweep, q, "MC")).ToArray();
            // How far over MC, in standard errors of the difference, where it is worse.
            string Over(long q) => $"{q} ({F(Error(sweep, q, "MLAE-noise"))} against {F(Error(sweep, q, "MC"))}, " +
                $"{F((Error(sweep, q, "MLAE-noise") - Error(sweep, q, "MC")) / Math.Sqrt(Math.Pow(Spread(sweep, q, "MLAE-noise"), 2) + Math.Pow(Spread(sweep, q, "MC"), 2)), "0.0")} standard errors)";
            lines.Add($"- {label}: plain MLAE {(saturated ? "has saturated" : "has not saturated")} (its error from {before} to {last} queries: {F(Error(sweep, before, "MLAE"))} → {F(Error(sweep, last, "MLAE"))}); " +
                $"at {last} queries it errs {F(ratio, "0.00")}x as much as the noise-aware MLAE (target ≥ 2x{(saturated ? "" : ", which applies where plain MLAE has saturated")}: **{(ratio >= 2 ? "met" : "not met")}**); " +
                $"the noise-aware MLAE is no worse than MC at {(worse.Length == 0 ? "every budget (**met**)" : $"every budget but {string.Join(", ", worse.Select(Over))} (**not met** there)")}.");
        }
        report.Text("**Targets.**\n" + string.Join("\n", lines));
    }
}
