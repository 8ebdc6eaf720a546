using QuantumRayTracing.Estimation;
namespace QuantumRayTracing.Supersampling;

/// <summary>
/// What `supersample` runs: the method, s (subpixels per side), and each method's own parameters, null where
/// the user left them to their defaults. <see cref="Problem"/> names any combination that cannot run.
/// </summary>
/// <param name="Method">The estimator.</param>
/// <param name="Side">s: each output pixel averages s x s subpixels.</param>
/// <param name="Queries">Per pixel and channel, for every method but QSS (default <see cref="DefaultQueries"/>; an upper bound for iqae, fae, bae and qss-bayes, which may stop below it); QSS's follow from its counter.</param>
/// <param name="Steps">QCoin's k (default <see cref="QCoinEstimator.DefaultSteps"/>).</param>
/// <param name="Levels">MLAE's K, plain or noise-aware (default <see cref="MaximumLikelihoodEstimator.DefaultLevels"/>).</param>
/// <param name="CounterBits">QSS's t (default: ceil(log2 N) for bit planes, 7 for continuous values).</param>
/// <param name="Planes">QSS bit planes P (default 8, exact for 8-bit inputs).</param>
/// <param name="Values">QSS's input: bit planes (default) or continuous values.</param>
public sealed record SupersampleSettings(
    SupersampleMethod Method,
    int Side,
    long? Queries = null,
    int? Steps = null,
    int? Levels = null,
    int? CounterBits = null,
    int? Planes = null,
    QssValues? Values = null)
{
    /// <summary>`supersample`'s method when none is given.</summary>
    public const SupersampleMethod DefaultMethod = SupersampleMethod.Qss;

    /// <summary>s when none is given: 4 x 4 = 16 subpixels, the thesis's.</summary>
    public const int DefaultSide = 4;

    /// <summary>Paper 003's fig. 1 budget.</summary>
    public const long DefaultQueries = 240;

    public const int DefaultPlanes = 8;

    /// <summary>Paper 003's fig. 1: QSS at 255 queries.</summary>
    public const int DefaultContinuousCounterBits = 7;

    public int Subpixels => Side * Side;

    /// <summary>Plain or noise-aware MLAE: the same schedule and --levels.</summary>
    public bool IsMlae => Method is SupersampleMethod.Mlae or SupersampleMethod.MlaeNoise;

    /// <summary>IQAE, FAE, BAE and QSS-Bayes: adaptive searches that may stop below the budget, so the budget is an upper bound.</summary>
    public bool MayStopBelowBudget => Method is SupersampleMethod.Iqae or SupersampleMethod.Fae or SupersampleMethod.Bae or SupersampleMethod.QssBayes;

    public QssValues QssValues => Values ?? QssValues.Planes;

    public long QueriesOrDefault => Queries ?? DefaultQueries;

    public int PlanesOrDefault => Planes ?? DefaultPlanes;

    public int CounterBitsOrDefault => CounterBits ?? (QssValues == QssValues.Continuous
        ? DefaultContinuousCounterBits
        : Math.Max(1, CoinRegisters.SubpixelQubits(Subpixels)));

    /// <summary>True when QSS reads bit planes through a lookup table (and so gives a confidence map).</summary>
    public bool UsesLookupTable => Method == SupersampleMethod.Qss && QssValues == QssValues.Planes;

    /// <summary>One line naming the first option combination that cannot run, or null.</summary>
    public string? Problem()
    {
        if (Method != SupersampleMethod.Qss)
        {
            if (CounterBits is not null) return "--counter-bits applies to --method qss only";
            if (Planes is not null) return "--planes applies to --method qss only";
            if (Values is not null) return "--qss-values applies to --method qss only";
        }
        else
        {
            if (Queries is not null)
                return "--queries does not apply to --method qss: a QSS run costs 2^(t+1) − 1 queries, so its count follows from --counter-bits (times --planes for bit planes)";
            if (QssValues == QssValues.Continuous && Planes is not null) return "--planes applies to --qss-values planes only";
        }
        if (Steps is not null && Method != SupersampleMethod.QCoin) return "--steps applies to --method qcoin only";
        if (Levels is not null && !IsMlae) return "--levels applies to --method mlae and mlae-noise only";
        var queries = QueriesOrDefault;
        if (Method == SupersampleMethod.QCoin)
        {
            var k = Steps ?? 1;
            if (queries < QCoinEstimator.MinimumQueries(k))
                return $"--method qcoin with {k} step{(k == 1 ? "" : "s")} needs at least {QCoinEstimator.MinimumQueries(k)} queries, got {queries}";
        }
        if (Method == SupersampleMethod.Fae && queries < FasterAmplitudeEstimator.MinimumQueries)
            return $"--method fae needs at least {FasterAmplitudeEstimator.MinimumQueries} queries (one flip after one Grover operator), got {queries}";
        if (IsMlae && Levels is { } levels && queries < MaximumLikelihoodEstimator.QueriesPerShot(levels))
            return $"--method {(Method == SupersampleMethod.Mlae ? "mlae" : "mlae-noise")} with --levels {levels} needs at least {MaximumLikelihoodEstimator.QueriesPerShot(levels)} queries, got {queries}";
        return null;
    }

    /// <summary>The estimator these settings describe; bit-plane QSS reads <paramref name="table"/> (N subpixels, t counter bits).</summary>
    public IMeanEstimator CreateEstimator(QssLookupTable? table = null)
    {
        if (Problem() is { } problem) throw new InvalidOperationException(problem);
        var queries = QueriesOrDefault;
        return Method switch
        {
            SupersampleMethod.Mc => new MonteCarloEstimator(queries),
            SupersampleMethod.QCoin => new QCoinEstimator(queries, Steps ?? QCoinEstimator.DefaultSteps(queries)),
            SupersampleMethod.Mlae => new MaximumLikelihoodEstimator(queries, Levels ?? MaximumLikelihoodEstimator.DefaultLevels(queries)),
            SupersampleMethod.MlaeNoise => new NoiseAwareMaximumLikelihoodEstimator(queries, Levels ?? MaximumLikelihoodEstimator.DefaultLevels(queries)),
            SupersampleMethod.Iqae => new IterativeAmplitudeEstimator(queries),
            SupersampleMethod.Fae => new FasterAmplitudeEstimator(queries),
            SupersampleMethod.Bae => new BayesianAmplitudeEstimator(queries),
            SupersampleMethod.QssBayes => new BayesianPhaseEstimator(queries),
            SupersampleMethod.PowerLaw => new PowerLawAmplitudeEstimator(queries),
            _ when QssValues == QssValues.Continuous => new QssEstimator(CounterBitsOrDefault),
            _ => new BitPlaneQssEstimator(CheckedTable(table), PlanesOrDefault),
        };
    }

    private QssLookupTable CheckedTable(QssLookupTable? table)
    {
        if (table is null || table.Subpixels != Subpixels || table.CounterBits != CounterBitsOrDefault)
            throw new ArgumentException($"bit-plane QSS needs the lookup table for {Subpixels} subpixels and {CounterBitsOrDefault} counter bits", nameof(table));
        return table;
    }
}
