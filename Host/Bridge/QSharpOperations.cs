namespace QuantumRayTracing.Bridge;

/// <summary>
/// The Q# operations the host calls, by full name: the "operations" of Quantum/entry-points.json, which
/// the Q# build checks against the sources, so that renaming one fails the build rather than a run.
/// </summary>
public static class QSharpOperations
{
    public const string MeasureDenseState = "QuantumRayTracing.Capacity.MeasureDenseState";

    public const string AccountForLogicalCounts = "QuantumRayTracing.Estimation.AccountForLogicalCounts";

    public const string ApplyGateGroverIterationOnNewRegisters = "QuantumRayTracing.Intersection.ApplyGateGroverIterationOnNewRegisters";

    public const string ApplyGateGroverSearch = "QuantumRayTracing.Intersection.ApplyGateGroverSearch";

    public const string ApplyGateGroverSearchWithUnitaryLookups = "QuantumRayTracing.Intersection.ApplyGateGroverSearchWithUnitaryLookups";

    public const string ApplyIntersectionOracleOnNewRegisters = "QuantumRayTracing.Intersection.ApplyIntersectionOracleOnNewRegisters";

    public const string ApplyPooledGroverIterationOnNewRegisters = "QuantumRayTracing.Intersection.ApplyPooledGroverIterationOnNewRegisters";

    public const string ApplyPooledGroverSearchWithUnitaryLookups = "QuantumRayTracing.Intersection.ApplyPooledGroverSearchWithUnitaryLookups";

    public const string ApplyPooledQueryOnNewRegisters = "QuantumRayTracing.Intersection.ApplyPooledQueryOnNewRegisters";

    public const string MeasureGateGroverBatch = "QuantumRayTracing.Intersection.MeasureGateGroverBatch";

    public const string MeasureGateGroverSearch = "QuantumRayTracing.Intersection.MeasureGateGroverSearch";

    public const string MeasureGroverBatch = "QuantumRayTracing.Search.MeasureGroverBatch";

    public const string MeasureGroverBatchOnDevice = "QuantumRayTracing.Search.MeasureGroverBatchOnDevice";

    public const string MeasureGroverBatchWithControlledZ = "QuantumRayTracing.Search.MeasureGroverBatchWithControlledZ";

    public const string MeasureGroverSchedules = "QuantumRayTracing.Search.MeasureGroverSchedules";

    public const string ApplyDirectCoin = "QuantumRayTracing.Supersampling.ApplyDirectCoin";

    public const string ApplyMeanCoin = "QuantumRayTracing.Supersampling.ApplyMeanCoin";

    public const string ApplyQss = "QuantumRayTracing.Supersampling.ApplyQss";

    public const string CountAncillaZerosBatch = "QuantumRayTracing.Supersampling.CountAncillaZerosBatch";

    public const string CountCoinHeads = "QuantumRayTracing.Supersampling.CountCoinHeads";

    public const string CountCoinHeadsBatch = "QuantumRayTracing.Supersampling.CountCoinHeadsBatch";

    public const string CountDirectCoinHeadsBatch = "QuantumRayTracing.Supersampling.CountDirectCoinHeadsBatch";

    public const string MeasureQssBatch = "QuantumRayTracing.Supersampling.MeasureQssBatch";

    public const string CountDirectCoinHeadsOnDeviceBatch = "QuantumRayTracing.Supersampling.CountDirectCoinHeadsOnDeviceBatch";

    public const string MeasureDirectQssOnDevice = "QuantumRayTracing.Supersampling.MeasureDirectQssOnDevice";

    public const string MeasureDirectQssOnDeviceBatch = "QuantumRayTracing.Supersampling.MeasureDirectQssOnDeviceBatch";

    public const string MeasureQssReadout = "QuantumRayTracing.Supersampling.MeasureQssReadout";
}
