// Simulates an OpenQASM 2.0 file on quantum-circuit (npm; an independent JavaScript simulator) and prints
// the exact outcome distribution of the classical register its final measurements fill:
//
//   node check-openqasm.mjs FILE   ->   {"register":"index","bits":3,"qubits":20,"probabilities":{"3":0.968,...}}
//
// The file's measurements must come last (as `qrt export --format qasm2` writes them). They are read
// for the qubit -> register bit map and left out of the simulation, because quantum-circuit would
// sample them; the distribution is the final state's marginal on the measured qubits, exact up to
// floating point, so it can be compared with the file's "ideal outcome probabilities" line.
// quantum-circuit applies each gate by looping over every basis state of the qubits it does not touch
// (2^(n-k) per matrix entry) and builds its masks with 32-bit shifts, so it reaches about 20 qubits in
// seconds to a minute and cannot hold 32 or more; check-openqasm-jsqubits.mjs goes further. With --serve it
// checks many files in one process (check-serve.mjs): loading quantum-circuit takes about a second.

import { createRequire } from "node:module";
import { readMeasuredRegister, registerDistribution } from "./qasm2-measured-register.mjs";
import { runCheck, UsageError } from "./check-serve.mjs";

const require = createRequire(import.meta.url);
const QuantumCircuit = require("quantum-circuit");

/** The reply for one file. */
function check([file]) {
  if (!file) throw new UsageError();
  const { kept, register, measured } = readMeasuredRegister(file);
  const circuit = new QuantumCircuit();
  circuit.importQASM(kept.join("\n"), (errors) => {
    if (errors.length > 0) throw new Error(`quantum-circuit cannot import the file: ${JSON.stringify(errors)}`);
  });
  circuit.run();
  // quantum-circuit keeps only nonzero amplitudes, keyed by basis index; qubit k is bit k of the index.
  const amplitudes = Object.entries(circuit.state).map(([key, a]) => [Number(key), a.re, a.im]);
  return { register, bits: measured.length, qubits: circuit.numQubits, probabilities: registerDistribution(amplitudes, measured) };
}

await runCheck("node check-openqasm.mjs FILE | --serve", check);
