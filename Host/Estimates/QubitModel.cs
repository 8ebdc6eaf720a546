using System.Text.Json.Nodes;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// One of the Resource Estimator's predefined physical qubit models with a QEC scheme:
/// gate-based <c>qubit_gate_ns_e3</c>, <c>qubit_gate_ns_e4</c> (superconducting-like, ns gates),
/// <c>qubit_gate_us_e3</c>, <c>qubit_gate_us_e4</c> (ion-like, µs gates), Majorana
/// <c>qubit_maj_ns_e4</c>, <c>qubit_maj_ns_e6</c>; error rates 10⁻³, 10⁻⁴, 10⁻⁶. Schemes:
/// <c>surface_code</c> for every model, <c>floquet_code</c> for the Majorana ones.
/// </summary>
public sealed record QubitModel(string Name, string QecScheme)
{
    public static readonly IReadOnlyList<string> Names =
        ["qubit_gate_ns_e3", "qubit_gate_ns_e4", "qubit_gate_us_e3", "qubit_gate_us_e4", "qubit_maj_ns_e4", "qubit_maj_ns_e6"];

    /// <summary>A superconducting-like gate model on the surface code, and a Majorana model on the Floquet code.</summary>
    public static readonly IReadOnlyList<QubitModel> Defaults =
        [new("qubit_gate_ns_e3", "surface_code"), new("qubit_maj_ns_e6", "floquet_code")];

    /// <summary>The estimator's default error budget, which every estimate of one circuit uses.</summary>
    public const double ErrorBudget = 1e-3;

    /// <summary>
    /// The error budget of the estimates on this model: the largest probability that one execution of
    /// the circuit fails, which the estimator splits between logical errors, T states and rotations.
    /// </summary>
    public double Budget { get; init; } = ErrorBudget;

    /// <summary>"qubit_gate_ns_e3" or "qubit_maj_ns_e6:floquet_code"; null with a message when the text names no valid pair.</summary>
    public static (QubitModel? Model, string? Error) Parse(string text)
    {
        var parts = text.Split(':');
        var name = parts[0];
        if (!Names.Contains(name)) return (null, $"unknown qubit model '{name}'; choose {string.Join(", ", Names)}");
        var scheme = parts.Length > 1 ? parts[1] : "surface_code";
        if (parts.Length > 2 || scheme is not ("surface_code" or "floquet_code"))
            return (null, $"'{text}': the QEC scheme must be surface_code or floquet_code");
        if (scheme == "floquet_code" && !name.StartsWith("qubit_maj", StringComparison.Ordinal))
            return (null, $"'{text}': the floquet_code needs a Majorana model (qubit_maj_ns_e4 or qubit_maj_ns_e6)");
        return (new QubitModel(name, scheme), null);
    }

    /// <summary>The estimator's parameter set for this model.</summary>
    public JsonObject Parameters() => new()
    {
        ["qubitParams"] = new JsonObject { ["name"] = Name },
        ["qecScheme"] = new JsonObject { ["name"] = QecScheme },
        ["errorBudget"] = Budget,
    };

    public override string ToString() => $"{Name}, {QecScheme}";
}
