using QuantumRayTracing.Bridge;
using QuantumRayTracing.Export;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Tests.Cli;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// The OpenQASM 2 export of a search compiles Q# <c>ApplyGateGroverSearchWithUnitaryLookups</c> (lookups
/// uncomputed by Toffolis) instead of <c>ApplyGateGroverSearch</c> with its measured uncomputations made
/// unitary afterwards: the file's gates must be the same, gate for gate, and its QIR must hold fewer
/// feedback branches (what makes the compile faster).
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
        Assert.NotNull(subject.UnitaryApply);
        using var bridge = new QSharpBridge();
        var fast = CircuitExporter.Export(bridge, subject, ExportFormat.Qasm2);
        var passed = CircuitExporter.Export(bridge, subject with { UnitaryApply = null }, ExportFormat.Qasm2);
        // The ideal-probabilities line is simulated separately for each program and may differ in the last bits.
        Assert.Equal(WithoutIdealLine(passed), WithoutIdealLine(fast));

        var measured = GateCounts.Of(QirReader.Read(CircuitExporter.Export(bridge, subject, ExportFormat.Qir)));
        var unitary = GateCounts.Of(QirReader.Read(CircuitExporter.Export(bridge, subject with { Apply = subject.UnitaryApply! }, ExportFormat.Qir)));
        Assert.True(unitary.Conditionals < measured.Conditionals, $"{unitary.Conditionals} feedback branches with unitary lookups, {measured.Conditionals} without");
    }

    private static string[] WithoutIdealLine(string text) =>
        text.Split('\n').Where(line => !line.StartsWith("// ideal outcome probabilities:", StringComparison.Ordinal)).ToArray();
}
