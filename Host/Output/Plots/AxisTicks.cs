namespace QuantumRayTracing.Output.Plots;

/// <summary>
/// Chooses the ticks of an axis. Linear axes get multiples of 1, 2 or 5 times a power of ten; log axes get
/// powers of ten with minor ticks at 2 to 9 times each, falling back to 1-2-5 multiples, then to all 1 to 9
/// multiples, then to linear steps when the range is too narrow to hold two of the coarser ticks. In each case
/// the densest choice whose labels do not collide wins.
/// </summary>
internal static class AxisTicks
{
    // Beyond this many ticks the labels could never fit; a coarser step is tried instead.
    private const int MaxTicks = 500;

    /// <summary>
    /// Ticks for <paramref name="axis"/>, aiming at one labelled tick per <paramref name="spacing"/> pixels;
    /// <paramref name="fits"/> says whether a set of ticks leaves room between its labels.
    /// </summary>
    public static IReadOnlyList<Tick> For(PlotAxis axis, double spacing, Func<IReadOnlyList<Tick>, bool> fits) =>
        axis.Scale == AxisScale.Log10
            ? Logarithmic(axis, spacing, fits)
            : Linear(axis.Low, axis.High, axis.PixelLength, spacing, at => at, fits);

    /// <summary>The smallest of 1, 2, 5 times a power of ten that is at least <paramref name="raw"/>.</summary>
    public static double NiceStep(double raw)
    {
        var power = Math.Pow(10, Math.Floor(Math.Log10(raw)));
        var fraction = raw / power;
        return (fraction <= 1 ? 1 : fraction <= 2 ? 2 : fraction <= 5 ? 5 : 10) * power;
    }

    /// <summary>The 1-2-5 step after <paramref name="step"/>.</summary>
    public static double NextStep(double step)
    {
        var power = Math.Pow(10, Math.Floor(Math.Log10(step)));
        // Compared with margins: a step of 10^k can come out of the logarithm as 9.99... times 10^(k-1).
        var fraction = step / power;
        return fraction < 1.5 ? 2 * power : fraction < 3.5 ? 5 * power : fraction < 7.5 ? 10 * power : 20 * power;
    }

    /// <summary>The 1-2-5 step before <paramref name="step"/>.</summary>
    public static double PreviousStep(double step)
    {
        var power = Math.Pow(10, Math.Floor(Math.Log10(step)));
        var fraction = step / power;
        return fraction < 1.5 ? 0.5 * power : fraction < 3.5 ? power : fraction < 7.5 ? 2 * power : 5 * power;
    }

    // Multiples of a 1-2-5 step between low and high (values), placed with toAt (values to axis units).
    private static IReadOnlyList<Tick> Linear(double low, double high, double pixels, double spacing,
        Func<double, double> toAt, Func<IReadOnlyList<Tick>, bool> fits)
    {
        var span = high - low;
        var raw = span / Math.Max(1, pixels / spacing);
        if (!double.IsFinite(span) || !(raw > 0)) return [];
        var scientific = TickLabels.NeedsScientific(Math.Max(Math.Abs(low), Math.Abs(high)));
        List<Tick>? coarsest = null;
        for (double step = NiceStep(raw), tries = 0; tries < 40 && double.IsFinite(step); step = NextStep(step), tries++)
        {
            var ticks = Multiples(low, high, step, scientific, toAt);
            if (ticks is null) continue;
            if (fits(ticks)) return ticks.Count >= 2 ? ticks : Denser(low, high, step, scientific, toAt, fits) ?? ticks;
            coarsest = ticks;
        }
        return coarsest ?? [];
    }

    // On a short axis the aimed-at spacing can leave a single label; a finer step may still fit two or more.
    private static List<Tick>? Denser(double low, double high, double step, bool scientific,
        Func<double, double> toAt, Func<IReadOnlyList<Tick>, bool> fits)
    {
        for (var tries = 0; tries < 3; tries++)
        {
            step = PreviousStep(step);
            var ticks = Multiples(low, high, step, scientific, toAt);
            if (ticks is null || !fits(ticks)) return null;
            if (ticks.Count >= 2) return ticks;
        }
        return null;
    }

    // Every multiple of `step` in [low, high]; null when there are too many to label.
    private static List<Tick>? Multiples(double low, double high, double step, bool scientific, Func<double, double> toAt)
    {
        double first = Math.Ceiling(low / step), last = Math.Floor(high / step);
        if (!(last - first < MaxTicks)) return null;
        // Steps far below the spacing of doubles at this magnitude cannot be told apart.
        if (Math.Abs(first) > 1e15 || Math.Abs(last) > 1e15) return [];
        var ticks = new List<Tick>();
        for (var k = first; k <= last; k++)
        {
            var value = k * step;
            ticks.Add(new Tick(toAt(value), TickLabels.Multiple(value, step, scientific), true));
        }
        return ticks;
    }

    private static IReadOnlyList<Tick> Logarithmic(PlotAxis axis, double spacing, Func<IReadOnlyList<Tick>, bool> fits)
    {
        double low = axis.Low, high = axis.High;
        double firstDecade = Math.Ceiling(low), lastDecade = Math.Floor(high);
        if (lastDecade > firstDecade) return Decades(low, high, axis.PixelLength / (high - low), fits);

        // Less than two powers of ten in range: label multiples within a decade, or failing that linear steps.
        var ticks = DecadeMultiples(low, high, [1, 2, 5], [3, 4, 6, 7, 8, 9]);
        if (ticks.Count(t => t.Major) < 2) ticks = DecadeMultiples(low, high, [1, 2, 3, 4, 5, 6, 7, 8, 9], []);
        if (ticks.Count(t => t.Major) >= 2) return Thinned(ticks, fits);
        return Linear(Math.Pow(10, low), Math.Pow(10, high), axis.PixelLength, spacing, Math.Log10, fits);
    }

    // Powers of ten, every `every`-th one labelled, with the smallest `every` whose labels fit.
    private static IReadOnlyList<Tick> Decades(double low, double high, double pixelsPerDecade, Func<IReadOnlyList<Tick>, bool> fits)
    {
        double first = Math.Ceiling(low), last = Math.Floor(high);
        List<Tick> ticks = [];
        foreach (var every in new[] { 1, 2, 3, 5, 10, 20, 25, 50, 100, 200, 250, 500 })
        {
            if ((last - first) / every >= MaxTicks) continue;
            ticks = [];
            for (var k = first; k <= last; k++)
            {
                var major = Math.Abs(k) % every == 0;
                // Unlabelled powers only where they stay a few pixels apart.
                if (major) ticks.Add(new Tick(k, TickLabels.PowerOfTen((int)k), true));
                else if (pixelsPerDecade >= 4) ticks.Add(new Tick(k, null, false));
            }
            // 2 to 9 times each power, where a decade is wide enough for eight marks to read as a scale.
            if (every == 1 && pixelsPerDecade >= 30)
                for (var k = Math.Floor(low); k <= last; k++)
                    for (var m = 2; m <= 9; m++)
                    {
                        var at = k + Math.Log10(m);
                        if (at >= low && at <= high) ticks.Add(new Tick(at, null, false));
                    }
            if (fits(ticks)) return ticks;
        }
        return ticks;
    }

    // Ticks at m times powers of ten within [low, high]: labelled majors for m in `labelled`, minors for `minor`.
    private static List<Tick> DecadeMultiples(double low, double high, int[] labelled, int[] minor)
    {
        var ticks = new List<Tick>();
        for (var k = Math.Floor(low); k <= Math.Ceiling(high); k++)
            for (var m = 1; m <= 9; m++)
            {
                var major = labelled.Contains(m);
                if (!major && !minor.Contains(m)) continue;
                var at = k + Math.Log10(m);
                if (at >= low && at <= high) ticks.Add(new Tick(at, major ? TickLabels.Compact(m * Math.Pow(10, k)) : null, major));
            }
        return ticks;
    }

    // Labels on every n-th labelled tick only, for the smallest n that fits; the others stay as unlabelled marks.
    private static IReadOnlyList<Tick> Thinned(List<Tick> ticks, Func<IReadOnlyList<Tick>, bool> fits)
    {
        var labelled = ticks.Where(t => t.Label is not null).OrderBy(t => t.At).ToList();
        IReadOnlyList<Tick> result = ticks;
        for (var every = 1; every <= labelled.Count; every++)
        {
            var keep = labelled.Where((_, i) => i % every == 0).ToHashSet();
            result = ticks.Select(t => t.Label is null || keep.Contains(t) ? t : t with { Label = null }).ToList();
            if (fits(result)) return result;
        }
        return result;
    }
}
