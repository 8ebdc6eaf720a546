using QuantumRayTracing.Bridge;
using QuantumRayTracing.Export;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Tests.Cli;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// The export of a search compiles Q# <c>ApplyGateGroverSearchWithUnitaryLookups</c> (lookups uncomputed by
/// Toffolis) instead of the gate engine's <c>ApplyGateGroverSearch</c>: made unitary, the two programs must have
/// the same gates, gate for gate, and the exported QIR must hold fewer feedback branches (what makes the
/// compile faster).
/// </summary>
public sealed class UnitaryLookupExportTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-unitary-lookup-");

    public void Dispose() => _scratch.Dispose();

    public static TheoryData<string> Subjects => ["tiny scene, pixel (3, 0)", "device experiment"];

    private ExportSubject Subject(string name) => name == "device experiment"
        ? DeviceExperimentExport.Subject()
        : SearchExport.ForPixel(DefaultScene.Load(new FileInfo(OpenQasmOnQuantumCircuitTests.TinyScene(_scratch))), 4, 4, 3, 0, OracleConstruction.Narrow, null);

    [Theory]
    [MemberData(nameof(Subjects))]
    public void Qasm2HasTheGatesOfTheMeasuredProgramMadeUnitary(string name)
    {
        var subject = Subject(name);
        Assert.Contains(QSharpOperations.ApplyGateGroverSearchWithUnitaryLookups + "(", subject.Apply, StringComparison.Ordinal);
        var gateEngine = subject with { Apply = subject.Apply.Replace(QSharpOperations.ApplyGateGroverSearchWithUnitaryLookups + "(", QSharpOperations.ApplyGateGroverSearch + "(", StringComparison.Ordinal) };
        using var bridge = new QSharpBridge();
        var fast = CircuitExporter.Export(bridge, subject, ExportFormat.Qasm2);
        var passed = CircuitExporter.Export(bridge, gateEngine, ExportFormat.Qasm2);
        // The ideal-probabilities line is simulated separately for each program and may differ in the last bits.
        Assert.Equal(WithoutIdealLine(passed), WithoutIdealLine(fast));

        var measured = GateCounts.Of(QirReader.Read(CircuitExporter.Export(bridge, gateEngine, ExportFormat.Qir)));
        var unitary = GateCounts.Of(QirReader.Read(CircuitExporter.Export(bridge, subject, ExportFormat.Qir)));
        Assert.True(unitary.Conditionals < measured.Conditionals, $"{unitary.Conditionals} feedback branches with unitary lookups, {measured.Conditionals} without");
    }

    private static string[] WithoutIdealLine(string text) =>
        text.Split('\n').Where(line => !line.StartsWith("// ideal outcome probabilities:", StringComparison.Ordinal)).ToArray();
}
