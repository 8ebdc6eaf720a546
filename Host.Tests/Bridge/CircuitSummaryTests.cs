using System.Diagnostics;
using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Bridge;

/// <summary>
/// The bridge's circuit summary (Quantum/circuit-summary.mjs) on a circuit written by hand in the
/// QDK's circuit format, against counts and depths worked out by hand.
/// </summary>
public sealed class CircuitSummaryTests
{
    // H(0); CX(0 → 1); CCX(0, 1 → 2); M(2); reset(2), as getCircuit lays it out in columns.
    private const string HandCircuit = """
        { "circuits": [ { "qubits": [ { "id": 0 }, { "id": 1 }, { "id": 2, "numResults": 1 } ], "componentGrid": [
          { "components": [ { "kind": "unitary", "gate": "H", "targets": [ { "qubit": 0 } ] } ] },
          { "components": [ { "kind": "unitary", "gate": "X", "targets": [ { "qubit": 1 } ], "controls": [ { "qubit": 0 } ] } ] },
          { "components": [ { "kind": "unitary", "gate": "X", "targets": [ { "qubit": 2 } ], "controls": [ { "qubit": 0 }, { "qubit": 1 } ] } ] },
          { "components": [ { "kind": "measurement", "gate": "M", "qubits": [ { "qubit": 2 } ], "results": [ { "qubit": 2, "result": 0 } ] } ] },
          { "components": [ { "kind": "ket", "gate": "0", "targets": [ { "qubit": 2 } ] } ] }
        ] } ], "version": 2 }
        """;

    [Fact]
    public void CountsAndDepthMatchAHandWorkedCircuit()
    {
        var summary = Summarise(HandCircuit);
        Assert.Equal(3, summary["qubits"]!.GetValue<int>());
        Assert.Equal(5, summary["operations"]!.GetValue<int>());

        // Native: H, CX, CCX, then the measurement and the reset on qubit 2, one step each.
        var native = summary["native"]!;
        Assert.Equal(new Dictionary<string, int> { ["H"] = 1, ["CX"] = 1, ["CCX"] = 1 }, Gates(native));
        Assert.Equal((3, 1, 1, 5), Tally(native));

        // CCX as qelib1's ccx (2 H, 6 CX, 4 T, 3 T†). Scheduled by hand with a = 0, b = 1, c = 2 free
        // after steps 2, 2, 0: h c → c 1; cx b,c → 3; tdg c → 4; cx a,c → 5; t c → 6; cx b,c → 7;
        // tdg c → 8; cx a,c → 9; t b → 8; t c → 10; h c → 11; cx a,b → 10; t a, tdg b → 11;
        // cx a,b → 12; then M on c → 12, reset → 13.
        var expanded = summary["qiskitCcx"]!;
        Assert.Equal(new Dictionary<string, int> { ["H"] = 3, ["CX"] = 7, ["T"] = 4, ["T†"] = 3 }, Gates(expanded));
        Assert.Equal((17, 1, 1, 13), Tally(expanded));
    }

    [Fact]
    public void ParallelGatesShareATimeStep()
    {
        // Four single-qubit gates on four qubits, then a CZ on two of them: depth 2, whatever the columns.
        var circuit = """
            { "circuits": [ { "qubits": [ { "id": 0 }, { "id": 1 }, { "id": 2 }, { "id": 3 } ], "componentGrid": [
              { "components": [ { "kind": "unitary", "gate": "T", "isAdjoint": true, "targets": [ { "qubit": 0 } ] } ] },
              { "components": [ { "kind": "unitary", "gate": "S", "targets": [ { "qubit": 1 } ] }, { "kind": "unitary", "gate": "H", "targets": [ { "qubit": 2 } ] } ] },
              { "components": [ { "kind": "unitary", "gate": "Ry", "args": ["0.5"], "targets": [ { "qubit": 3 } ] } ] },
              { "components": [ { "kind": "unitary", "gate": "Z", "targets": [ { "qubit": 3 } ], "controls": [ { "qubit": 0 } ] } ] }
            ] } ], "version": 2 }
            """;
        var native = Summarise(circuit)["native"]!;
        Assert.Equal(new Dictionary<string, int> { ["T†"] = 1, ["S"] = 1, ["H"] = 1, ["Ry"] = 1, ["CZ"] = 1 }, Gates(native));
        Assert.Equal((5, 0, 0, 2), Tally(native));
    }

    private static Dictionary<string, int> Gates(JsonNode tally) =>
        tally["gates"]!.AsObject().ToDictionary(p => p.Key, p => p.Value!.GetValue<int>());

    private static (int Gates, int Measurements, int Resets, int Depth) Tally(JsonNode tally) =>
        (tally["gateCount"]!.GetValue<int>(), tally["measurements"]!.GetValue<int>(), tally["resets"]!.GetValue<int>(), tally["depth"]!.GetValue<int>());

    /// <summary>Runs summariseCircuit from the bridge's module in Node on <paramref name="circuit"/>.</summary>
    private static JsonNode Summarise(string circuit)
    {
        var module = new Uri(Path.Combine(QuantumProject.Directory, "circuit-summary.mjs")).AbsoluteUri;
        var script = $"import {{ summariseCircuit }} from {JsonValue.Create(module).ToJsonString()};\n"
                     + "let text = ''; process.stdin.on('data', d => text += d);\n"
                     + "process.stdin.on('end', () => console.log(JSON.stringify(summariseCircuit(JSON.parse(text)))));\n";
        var start = new ProcessStartInfo("node") { RedirectStandardInput = true, RedirectStandardOutput = true, RedirectStandardError = true };
        foreach (var argument in new[] { "--input-type=module", "-e", script }) start.ArgumentList.Add(argument);
        using var node = Process.Start(start)!;
        node.StandardInput.Write(circuit);
        node.StandardInput.Close();
        var output = node.StandardOutput.ReadToEnd();
        var errors = node.StandardError.ReadToEnd();
        node.WaitForExit();
        Assert.True(node.ExitCode == 0, errors);
        return JsonNode.Parse(output)!;
    }
}
