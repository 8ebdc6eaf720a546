using QuantumRayTracing.Export;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// The QIR reader and the two OpenQASM writers on QIR written by hand in the QDK's adaptive-profile form:
/// an AND computed with a Toffoli and uncomputed by measurement and feedback, then the register measured.
/// </summary>
public sealed class QirReaderTests
{
    private static string Qir(string body) => $$"""
        %Result = type opaque
        %Qubit = type opaque

        define i64 @ENTRYPOINT__main() #0 {
        block_0:
          call void @__quantum__rt__initialize(i8* null)
        {{body}}
          call void @__quantum__rt__array_record_output(i64 2, i8* null)
          call void @__quantum__rt__result_record_output(%Result* inttoptr (i64 1 to %Result*), i8* null)
          call void @__quantum__rt__result_record_output(%Result* inttoptr (i64 2 to %Result*), i8* null)
          ret i64 0
        }

        attributes #0 = { "entry_point" "qir_profiles"="adaptive_profile" "required_num_qubits"="3" "required_num_results"="3" }
        """;

    // ry on qubit 0 (an exact double), h on 1, AND(0, 1 → 2) as a Toffoli, s† on 1, the AND's measured
    // uncomputation (h, measure and reset, cz when One), then qubits 0 and 1 measured as the register.
    private const string AndUncomputedByMeasurement = """
          call void @__quantum__qis__ry__body(double 0.9272952180016123, %Qubit* null)
          call void @__quantum__qis__h__body(%Qubit* inttoptr (i64 1 to %Qubit*))
          call void @__quantum__qis__ccx__body(%Qubit* null, %Qubit* inttoptr (i64 1 to %Qubit*), %Qubit* inttoptr (i64 2 to %Qubit*))
          call void @__quantum__qis__s__adj(%Qubit* inttoptr (i64 1 to %Qubit*))
          call void @__quantum__qis__h__body(%Qubit* inttoptr (i64 2 to %Qubit*))
          call void @__quantum__qis__mresetz__body(%Qubit* inttoptr (i64 2 to %Qubit*), %Result* inttoptr (i64 0 to %Result*))
          %var_1 = call i1 @__quantum__rt__read_result(%Result* inttoptr (i64 0 to %Result*))
          br i1 %var_1, label %block_1, label %block_2
        block_1:
          call void @__quantum__qis__cz__body(%Qubit* null, %Qubit* inttoptr (i64 1 to %Qubit*))
          br label %block_2
        block_2:
          call void @__quantum__qis__mresetz__body(%Qubit* null, %Result* inttoptr (i64 1 to %Result*))
          call void @__quantum__qis__mresetz__body(%Qubit* inttoptr (i64 1 to %Qubit*), %Result* inttoptr (i64 2 to %Result*))
        """;

    [Fact]
    public void ReadsGatesMeasurementsFeedbackAndOutputs()
    {
        var circuit = QirReader.Read(Qir(AndUncomputedByMeasurement));
        Assert.Equal(3, circuit.Qubits);
        Assert.Equal([1, 2], circuit.Outputs);
        CircuitStep[] expected =
            [
                new GateStep("ry", [0], 0.9272952180016123), new GateStep("h", [1]), new GateStep("ccx", [0, 1, 2]), new GateStep("sdg", [1]),
                new GateStep("h", [2]), new MeasureStep(2, 0), new ConditionalStep(0, [new GateStep("cz", [0, 1])]), new MeasureStep(0, 1), new MeasureStep(1, 2),
            ];
        Assert.Equal(expected.Select(Plain), circuit.Steps.Select(Plain));
    }

    [Fact]
    public void Qasm2UncomputesTheAndWithAToffoli()
    {
        var text = Qasm2Writer.Write(UnitaryUncomputation.Apply(QirReader.Read(Qir(AndUncomputedByMeasurement))), "", "index");
        Assert.Equal("""
            OPENQASM 2.0;
            include "qelib1.inc";
            qreg q[3];
            creg index[2];
            ry(0.9272952180016123) q[0];
            h q[1];
            ccx q[0], q[1], q[2];
            sdg q[1];
            ccx q[0], q[1], q[2];
            measure q[0] -> index[0];
            measure q[1] -> index[1];

            """.ReplaceLineEndings("\n"), text);
    }

    [Fact]
    public void Qasm3KeepsTheMeasurementAndFeedback()
    {
        var text = Qasm3Writer.Write(QirReader.Read(Qir(AndUncomputedByMeasurement)), "", "index");
        Assert.Contains("bit uncompute;\n", text, StringComparison.Ordinal);
        Assert.Contains("h q[2];\nuncompute = measure q[2];\nreset q[2];\nif (uncompute) { cz q[0], q[1]; }\nindex[0] = measure q[0];\nindex[1] = measure q[1];\n", text, StringComparison.Ordinal);
    }

    [Fact]
    public void MeasurementWithoutItsAndPatternHasNoUnitaryForm()
    {
        // The same program without the H before the measurement: not an AND's uncomputation.
        var circuit = QirReader.Read(Qir(AndUncomputedByMeasurement.Replace("  call void @__quantum__qis__h__body(%Qubit* inttoptr (i64 2 to %Qubit*))\n", "", StringComparison.Ordinal)));
        var e = Assert.Throws<InvalidOperationException>(() => UnitaryUncomputation.Apply(circuit));
        Assert.Contains("has no unitary form", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void OtherControlFlowIsRefused()
    {
        var loop = AndUncomputedByMeasurement.Replace("br label %block_2\nblock_2:", "br label %block_0\nblock_2:", StringComparison.Ordinal);
        Assert.Throws<FormatException>(() => QirReader.Read(Qir(loop)));
    }

    // Records compare their lists by reference; compare what they print instead.
    private static string Plain(CircuitStep step) => step switch
    {
        GateStep g => $"{g.Gate}({g.Angle}) {string.Join(',', g.Qubits)}",
        ConditionalStep c => $"if {c.Result}: {string.Join("; ", c.Gates.Select(Plain))}",
        _ => step.ToString(),
    };
}
