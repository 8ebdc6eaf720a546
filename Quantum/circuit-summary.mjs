// Counts and depth of a circuit the QDK extracted with getCircuit (generationMethod "simulate",
// groupByScope false): a flat list of the simulator's intrinsic operations, laid out in columns.
//
// Gate kinds are named by their controls: X with one control is CX, with two CCX; T with
// isAdjoint is T†. Measurements (M) and resets (the QDK draws a reset as a ket |0⟩) are kept apart
// from the gates. Depth: every operation, measurements and resets included, takes one time step on
// each qubit it touches (targets and controls) and starts as soon as all of them are free; the
// depth is the last step used. That is Qiskit's QuantumCircuit.depth() on the same list.
//
// The same summary is also given with each CCX replaced by Qiskit's 15-gate definition of ccx
// (2 H, 6 CX, 4 T and 3 T†), the basis in which Qiskit counts a Toffoli circuit's gates and depth.
//
// On request, the native circuit's noise exposure (noise-exposure.mjs): per gate kind, the noise locations at which
// no Pauli error, only X and Y, or every Pauli can harm the run.

import { Circuit, locationPatterns, noiseExposure, trackableOrder } from "./noise-exposure.mjs";
import { gradedHarm } from "./noise-harm.mjs";

/** Qiskit's CCXGate definition on controls a, b and target c, as [gate, qubits] pairs. */
function qiskitCcx(a, b, c) {
  return [
    ["H", [c]], ["CX", [b, c]], ["T†", [c]], ["CX", [a, c]], ["T", [c]], ["CX", [b, c]], ["T†", [c]], ["CX", [a, c]],
    ["T", [b]], ["T", [c]], ["H", [c]], ["CX", [a, b]], ["T", [a]], ["T†", [b]], ["CX", [a, b]],
  ];
}

/** An operation's kind name and every qubit it touches. */
export function describe(op) {
  if (op.kind === "measurement") return { kind: "M", qubits: op.qubits.map((r) => r.qubit), measurement: true };
  if (op.kind === "ket") return { kind: "Reset", qubits: op.targets.map((r) => r.qubit), reset: true };
  const controls = (op.controls ?? []).filter((r) => r.result === undefined).map((r) => r.qubit);
  const targets = op.targets.map((r) => r.qubit);
  const kind = "C".repeat(controls.length) + op.gate + (op.isAdjoint ? "†" : "");
  return { kind, gate: op.gate, qubits: [...controls, ...targets], controls, targets, conditional: op.isConditional === true };
}

class Tally {
  constructor() {
    this.gates = {};
    this.gateCount = 0;
    this.measurements = 0;
    this.resets = 0;
    this.free = new Map(); // qubit -> first free time step
    this.depth = 0;
  }

  add(kind, qubits, what = {}) {
    if (what.measurement) this.measurements++;
    else if (what.reset) this.resets++;
    else {
      this.gates[kind] = (this.gates[kind] ?? 0) + 1;
      this.gateCount++;
    }
    let start = 0;
    for (const q of qubits) start = Math.max(start, this.free.get(q) ?? 0);
    for (const q of qubits) this.free.set(q, start + 1);
    this.depth = Math.max(this.depth, start + 1);
  }

  result() {
    return { gates: this.gates, gateCount: this.gateCount, measurements: this.measurements, resets: this.resets, depth: this.depth };
  }
}

/**
 * Summarises circuit.circuits[0]: qubits, gates by kind, measurements, resets and depth in the QDK's
 * gate set ("native") and with CCX expanded as Qiskit defines it ("qiskitCcx"); with `withExposure` also the noise
 * exposure ("exposure", noise-exposure.mjs) and, given `marked` (the search's marked indices), its graded harm ("harm",
 * noise-harm.mjs), which take far longer than the rest.
 */
export function summariseCircuit(group, withExposure = false, marked = null, sampling = {}) {
  const circuit = group.circuits[0];
  const native = new Tally();
  const expanded = new Tally();
  let operations = 0;
  let conditional = 0;
  const described = [];
  for (const column of circuit.componentGrid) {
    for (const op of column.components) {
      if (op.children && op.children.length > 0) throw new Error("expected a flat circuit (groupByScope false)");
      operations++;
      const d = describe(op);
      described.push(d);
      if (d.conditional) conditional++;
      native.add(d.kind, d.qubits, d);
      if (d.kind === "CCX") for (const [gate, qubits] of qiskitCcx(d.controls[0], d.controls[1], d.targets[0])) expanded.add(gate, qubits);
      else expanded.add(d.kind, d.qubits, d);
    }
  }
  return {
    qubits: circuit.qubits.length, operations, conditional, native: native.result(), qiskitCcx: expanded.result(),
    ...(withExposure ? exposureOf(described, marked, sampling) : {}),
  };
}

/**
 * The exposure, and the graded harm when `marked` (the search's marked indices) is given: "harm" over every location,
 * "outsideHarm" at the preparation and the final measurement, "harmSampling" and "harmChannels" (noise-harm.mjs), each location's pattern found once.
 */
function exposureOf(traced, marked, sampling) {
  const ops = trackableOrder(traced);
  const circuit = new Circuit(ops);
  const patterns = locationPatterns(ops, circuit);
  const graded = marked ? gradedHarm(ops, marked, circuit, { ...sampling, patterns }) : null;
  return {
    exposure: noiseExposure(ops, circuit, patterns),
    ...(graded ? { harm: graded.harm, outsideHarm: graded.outsideHarm, harmSections: graded.sections, harmSampling: graded.sampling, harmChannels: graded.channels } : {}),
  };
}
