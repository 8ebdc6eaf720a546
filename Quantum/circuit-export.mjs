// What `qrt export` asks of the QDK for one circuit: its QIR and the exact outcome distribution of the
// register it measures.
//
// The circuit is given as a Q# expression of type Qubit[] => Unit (an operation partially applied to
// everything but its register), the register's width, and how many of its first qubits are measured
// (all of them but for QSS, whose coin qubits stay entangled with the measured counter). The bridge wraps
// it in an entry point that allocates the register, applies the operation and measures the measured
// qubits (MResetEachZ, so the QIR records one result per qubit, bit 0 first), and compiles that to QIR.
// A second operation applies the same circuit and dumps the simulator's state before the measurement:
// every work qubit is released by then, so the dump holds the register alone, and the measured qubits'
// distribution is the sum of squared amplitudes over the values of the unmeasured ones.

/** The namespace of the two operations the bridge adds. */
export const exportEntryNamespace = "QuantumRayTracingExportEntry";

/** Q# source of the entry point (measured) and of DumpState (the state before the measurement). */
export function exportEntrySource(apply, qubits, measured) {
  return `namespace ${exportEntryNamespace} {
    @EntryPoint() operation Main() : Result[] { use register = Qubit[${qubits}]; (${apply})(register); MResetEachZ(register[...${measured - 1}]) }
    operation DumpState() : Unit { use register = Qubit[${qubits}]; (${apply})(register); Std.Diagnostics.DumpMachine(); ResetAll(register); }
}`;
}

/**
 * The probability of each value of the register's first `measured` qubits (bit k of the value is register
 * qubit k) from a DumpMachine state, whose labels list the allocated qubits in allocation order, qubit 0
 * first: the marginal, summed over the other qubits.
 */
export function registerDistribution(dump, qubits, measured) {
  if (dump.qubitCount !== qubits) {
    throw new Error(`the state holds ${dump.qubitCount} qubits after the circuit, expected the ${qubits} of its register: a work qubit was not released`);
  }
  const probabilities = new Array(2 ** measured).fill(0);
  for (const [label, [re, im]] of Object.entries(dump.state)) {
    const bits = label.replace(/[|⟩]/g, "");
    let value = 0;
    for (let k = 0; k < measured; k++) if (bits[k] === "1") value += 2 ** k;
    probabilities[value] += re * re + im * im;
  }
  return probabilities;
}
