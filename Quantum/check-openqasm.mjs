// Simulates an OpenQASM 2.0 file on quantum-circuit (npm; an independent JavaScript simulator) and prints
// the exact outcome distribution of the classical register its final measurements fill:
//
//   node check-openqasm.mjs FILE   ->   {"register":"index","bits":3,"qubits":20,"probabilities":{"3":0.968,...}}
//
// The file's measurements must come last (as `qrt export --format qasm2` writes them). They are read
// for the qubit -> register bit map and left out of the simulation, because quantum-circuit would
// sample them; the distribution is the final state's marginal on the measured qubits, exact up to
// floating point, so it can be compared with the file's "ideal outcome probabilities" line.

import fs from "node:fs";
import { createRequire } from "node:module";

const require = createRequire(import.meta.url);
const QuantumCircuit = require("quantum-circuit");

const file = process.argv[2];
if (!file) {
  console.error("usage: node check-openqasm.mjs FILE");
  process.exit(2);
}
const lines = fs.readFileSync(file, "utf8").split("\n");
const measured = []; // [qubit, register, bit]
const kept = [];
for (const line of lines) {
  const m = line.match(/^\s*measure\s+q\[(\d+)\]\s*->\s*(\w+)\[(\d+)\]\s*;\s*$/);
  if (m) measured.push([Number(m[1]), m[2], Number(m[3])]);
  else if (measured.length > 0 && line.trim() !== "") throw new Error(`a statement follows the measurements: ${line}`);
  else kept.push(line);
}
if (measured.length === 0) throw new Error("the file measures nothing");
const register = measured[0][1];
if (measured.some(([, r]) => r !== register)) throw new Error("the measurements fill more than one register");

const circuit = new QuantumCircuit();
circuit.importQASM(kept.join("\n"), (errors) => {
  if (errors.length > 0) throw new Error(`quantum-circuit cannot import the file: ${JSON.stringify(errors)}`);
});
circuit.run();

// quantum-circuit keeps only nonzero amplitudes, keyed by basis index; qubit k is bit k of the index.
const probabilities = {};
for (const [key, amplitude] of Object.entries(circuit.state)) {
  const index = Number(key);
  let value = 0;
  for (const [qubit, , bit] of measured) if (Math.floor(index / 2 ** qubit) % 2 === 1) value += 2 ** bit;
  probabilities[value] = (probabilities[value] ?? 0) + amplitude.re * amplitude.re + amplitude.im * amplitude.im;
}
console.log(JSON.stringify({ register, bits: measured.length, qubits: circuit.numQubits, probabilities }));
