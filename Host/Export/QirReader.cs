using System.Globalization;
using System.Text.RegularExpressions;

namespace QuantumRayTracing.Export;

/// <summary>
/// Reads the straight-line QIR the QDK compiles our circuits to (adaptive profile, every loop unrolled and
/// every classical value folded) into a <see cref="QirCircuit"/>. The only control flow it accepts is the
/// one a measurement-based uncomputation makes: read a result, branch to a block of gates, join. Anything
/// else is refused, so a circuit this reader returns is the program, step for step.
/// </summary>
public static partial class QirReader
{
    public static QirCircuit Read(string qir)
    {
        var qubits = RequiredQubits().Match(qir) is { Success: true } m
            ? int.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture)
            : throw new FormatException("the QIR names no required_num_qubits");
        var body = EntryBody(qir);
        var steps = new List<CircuitStep>();
        var outputs = new List<int>();
        var resultOf = new Dictionary<string, int>();
        List<GateStep>? branch = null;
        (int Result, string Join)? open = null;
        string? expectedBlock = null;
        foreach (var raw in body)
        {
            var line = raw.Trim();
            if (line.Length == 0) continue;
            if (line.EndsWith(':'))
            {
                var label = line[..^1];
                if (expectedBlock is not null && label != expectedBlock)
                    throw new FormatException($"QIR block {label} follows a branch to {expectedBlock}: control flow beyond measurement feedback is not supported");
                if (open is { } o && label == o.Join)
                {
                    steps.Add(new ConditionalStep(o.Result, branch!));
                    (open, branch) = (null, null);
                }
                expectedBlock = null;
                continue;
            }
            if (Branch().Match(line) is { Success: true } br)
            {
                if (open is not null || !resultOf.TryGetValue(br.Groups[1].Value, out var result))
                    throw new FormatException($"unsupported QIR branch: {line}");
                open = (result, br.Groups[3].Value);
                branch = [];
                expectedBlock = br.Groups[2].Value;
                continue;
            }
            if (Jump().Match(line) is { Success: true } jump)
            {
                var target = jump.Groups[1].Value;
                if (open is { } o ? target != o.Join : false) throw new FormatException($"unsupported QIR jump: {line}");
                expectedBlock = target;
                continue;
            }
            if (ReadResult().Match(line) is { Success: true } read)
            {
                resultOf[read.Groups[1].Value] = Pointer(read.Groups[2].Value);
                continue;
            }
            if (RecordResult().Match(line) is { Success: true } record)
            {
                outputs.Add(Pointer(record.Groups[1].Value));
                continue;
            }
            if (line.StartsWith("call void @__quantum__rt__", StringComparison.Ordinal) || line.StartsWith("ret ", StringComparison.Ordinal)) continue;
            if (Call().Match(line) is { Success: true } call)
            {
                var step = Step(call.Groups[1].Value, call.Groups[2].Value, SplitArguments(call.Groups[3].Value), line);
                if (branch is not null)
                    branch.Add(step as GateStep ?? throw new FormatException($"a measurement inside a feedback branch is not supported: {line}"));
                else steps.Add(step);
                continue;
            }
            throw new FormatException($"unsupported QIR instruction: {line}");
        }
        if (open is not null) throw new FormatException("the QIR ends inside a feedback branch");
        return new QirCircuit(qubits, steps, outputs);
    }

    /// <summary>The lines between the entry point's opening and closing braces.</summary>
    private static IEnumerable<string> EntryBody(string qir)
    {
        var lines = qir.Split('\n');
        var start = Array.FindIndex(lines, l => l.StartsWith("define ", StringComparison.Ordinal) && l.Contains("@ENTRYPOINT__main", StringComparison.Ordinal));
        if (start < 0) throw new FormatException("the QIR has no entry point");
        var end = Array.FindIndex(lines, start, l => l.TrimEnd() == "}");
        return lines[(start + 1)..end];
    }

    private static CircuitStep Step(string name, string variant, IReadOnlyList<string> arguments, string line)
    {
        var adjoint = variant == "adj";
        if (name == "mresetz") return new MeasureStep(Pointer(arguments[0]), Pointer(arguments[1]));
        var gate = (name, adjoint) switch
        {
            ("s", true) => "sdg",
            ("t", true) => "tdg",
            (_, true) => throw new FormatException($"unsupported adjoint gate: {line}"),
            ("x" or "y" or "z" or "h" or "s" or "t" or "cx" or "cy" or "cz" or "ccx" or "swap" or "rx" or "ry" or "rz", false) => name,
            _ => throw new FormatException($"unsupported QIR gate {name}: {line}"),
        };
        double? angle = gate is "rx" or "ry" or "rz"
            ? double.Parse(arguments[0].Replace("double ", "", StringComparison.Ordinal), NumberStyles.Float, CultureInfo.InvariantCulture)
            : null;
        var qubits = arguments.Skip(angle is null ? 0 : 1).Select(Pointer).ToArray();
        return new GateStep(gate, qubits, angle);
    }

    /// <summary>The number in a QIR qubit or result pointer: <c>%Qubit* inttoptr (i64 N to %Qubit*)</c>, or <c>null</c> for 0.</summary>
    private static int Pointer(string text) =>
        text.TrimEnd().EndsWith("null", StringComparison.Ordinal) ? 0
        : PointerNumber().Match(text) is { Success: true } m ? int.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture)
        : throw new FormatException($"not a QIR qubit or result: {text}");

    /// <summary>Splits a call's arguments at top-level commas (the pointers' parentheses hold none, but be safe).</summary>
    private static IReadOnlyList<string> SplitArguments(string text)
    {
        var parts = new List<string>();
        var depth = 0;
        var start = 0;
        for (var k = 0; k < text.Length; k++)
        {
            if (text[k] == '(') depth++;
            else if (text[k] == ')') depth--;
            else if (text[k] == ',' && depth == 0)
            {
                parts.Add(text[start..k].Trim());
                start = k + 1;
            }
        }
        if (text.Trim().Length > 0) parts.Add(text[start..].Trim());
        return parts;
    }

    [GeneratedRegex("\"required_num_qubits\"=\"(\\d+)\"")]
    private static partial Regex RequiredQubits();

    [GeneratedRegex(@"^br i1 (%[\w.]+), label %([\w.]+), label %([\w.]+)$")]
    private static partial Regex Branch();

    [GeneratedRegex(@"^br label %([\w.]+)$")]
    private static partial Regex Jump();

    [GeneratedRegex(@"^(%[\w.]+) = call i1 @__quantum__rt__read_result\((.*)\)$")]
    private static partial Regex ReadResult();

    [GeneratedRegex(@"^call void @__quantum__rt__result_record_output\((%Result\*[^,]*),")]
    private static partial Regex RecordResult();

    [GeneratedRegex(@"^call void @__quantum__qis__(\w+?)__(body|adj)\((.*)\)$")]
    private static partial Regex Call();

    [GeneratedRegex(@"i64 (\d+) to")]
    private static partial Regex PointerNumber();
}
