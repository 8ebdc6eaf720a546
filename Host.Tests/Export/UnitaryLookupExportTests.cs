using QuantumRayTracing.Bridge;
using QuantumRayTracing.Export;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// The export of a search compiles Q# <c>ApplyGateGroverSearchWithUnitaryLookups</c> (lookups uncomputed by
/// Toffolis) instead of the gate engine's <c>ApplyGateGroverSearch</c>: made unitary, the two programs must have
/// the same gates, gate for gate, and the exported QIR must hold fewer feedback branches (what makes the
/// compile faster). The exports run on one shared bridge (<see cref="ExportCache.Export"/>).
/// </summary>
public sealed class UnitaryLookupExportTests
{
    public static TheoryData<string> Subjects => ["tiny scene, pixel (3, 0)", "device experiment"];

    private static ExportSubject Subject(string name) => name == "device experiment"
        ? DeviceExperimentExport.Subject()
        : SearchExport.ForPixel(DefaultScene.Load(new FileInfo(OpenQasmOnQuantumCircuitTests.TinyScene())), 4, 4, 3, 0, OracleConstruction.Narrow, null);

    [Theory]
    [MemberData(nameof(Subjects))]
    public void Qasm2HasTheGatesOfTheMeasuredProgramMadeUnitary(string name)
    {
        var subject = Subject(name);
        Assert.Contains(QSharpOperations.ApplyGateGroverSearchWithUnitaryLookups + "(", subject.Apply, StringComparison.Ordinal);
        var gateEngine = subject with { Apply = subject.Apply.Replace(QSharpOperations.ApplyGateGroverSearchWithUnitaryLookups + "(", QSharpOperations.ApplyGateGroverSearch + "(", StringComparison.Ordinal) };
        var fast = ExportCache.Export(subject, ExportFormat.Qasm2);
        var passed = ExportCache.Export(gateEngine, ExportFormat.Qasm2);
        // The ideal-probabilities line is simulated separately for each program and may differ in the last bits.
        Assert.Equal(WithoutIdealLine(passed), WithoutIdealLine(fast));

        var measured = GateCounts.Of(QirReader.Read(ExportCache.Export(gateEngine, ExportFormat.Qir)));
        var unitary = GateCounts.Of(QirReader.Read(ExportCache.Export(subject, ExportFormat.Qir)));
        Assert.True(unitary.Conditionals < measured.Conditionals, $"{unitary.Conditionals} feedback branches with unitary lookups, {measured.Conditionals} without");
    }

    /// <summary>
    /// Every export unloads by a second lookup, so compact (the engines' default, which unloads by measurement)
    /// exports as narrow: the same file but for the oracle line, which says so.
    /// </summary>
    [Fact]
    public void CompactExportsAsNarrow()
    {
        var scene = DefaultScene.Load(new FileInfo(OpenQasmOnQuantumCircuitTests.TinyScene()));
        string Export(OracleConstruction construction) =>
            ExportCache.Export(SearchExport.ForPixel(scene, 4, 4, 3, 0, construction, null), ExportFormat.Qasm2);
        var compact = Export(OracleConstruction.Compact);
        Assert.Contains("// oracle: compact (2 axes tested, 2 bound register(s)), unload by a second lookup (the engines' compact oracle unloads by measurement, an unlookup the QDK cannot compile to QIR; so this is the narrow oracle's circuit)\n", compact, StringComparison.Ordinal);
        static string[] Body(string text) => WithoutIdealLine(text).Where(line => !line.StartsWith("// oracle: ", StringComparison.Ordinal)).ToArray();
        Assert.Equal(Body(Export(OracleConstruction.Narrow)), Body(compact));
    }

    private static string[] WithoutIdealLine(string text) =>
        text.Split('\n').Where(line => !line.StartsWith("// ideal outcome probabilities:", StringComparison.Ordinal)).ToArray();
}
