// What `qrt export` asks of the QDK for one circuit: its QIR and the exact outcome distribution of the
// register it measures.
//
// The circuit is given as a Q# expression of type Qubit[] => Unit (an operation partially applied to
// everything but its register) and the register's width. The bridge wraps it in an entry point that
// allocates the register, applies the operation and measures the register (MResetEachZ, so the QIR
// records one result per qubit, bit 0 first), and compiles that to QIR. A second operation applies the
// same circuit and dumps the simulator's state before the measurement: every work qubit is released by
// then, so the dump holds the register alone and its squared amplitudes are the outcome distribution.

/** The namespace of the two operations the bridge adds. */
export const exportEntryNamespace = "QuantumRayTracingExportEntry";

/** Q# source of the entry point (measured) and of DumpState (the state before the measurement). */
export function exportEntrySource(apply, qubits) {
  return `namespace ${exportEntryNamespace} {
    @EntryPoint() operation Main() : Result[] { use register = Qubit[${qubits}]; (${apply})(register); MResetEachZ(register) }
    operation DumpState() : Unit { use register = Qubit[${qubits}]; (${apply})(register); Std.Diagnostics.DumpMachine(); ResetAll(register); }
}`;
}

/**
 * The probability of each register value (bit k of the value is register qubit k) from a DumpMachine
 * state, whose labels list the allocated qubits in allocation order, qubit 0 first.
 */
export function registerDistribution(dump, qubits) {
  if (dump.qubitCount !== qubits) {
    throw new Error(`the state holds ${dump.qubitCount} qubits after the circuit, expected the ${qubits} of its register: a work qubit was not released`);
  }
  const probabilities = new Array(2 ** qubits).fill(0);
  for (const [label, [re, im]] of Object.entries(dump.state)) {
    const bits = label.replace(/[|⟩]/g, "");
    let value = 0;
    for (let k = 0; k < qubits; k++) if (bits[k] === "1") value += 2 ** k;
    probabilities[value] += re * re + im * im;
  }
  return probabilities;
}
