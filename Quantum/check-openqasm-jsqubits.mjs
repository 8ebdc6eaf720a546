// Simulates an OpenQASM 2.0 file on jsqubits (npm; an independent JavaScript simulator whose state is
// sparse: each gate visits only the nonzero amplitudes) and prints the exact outcome distribution of the
// classical register its final measurements fill, in the same form as check-openqasm.mjs:
//
//   node check-openqasm-jsqubits.mjs FILE   ->   {"register":"index","bits":2,"qubits":28,"probabilities":{"2":1,...}}
//
// jsqubits has no OpenQASM import, so each gate statement of the file is called as the jsqubits gate of
// the same name and matrix (sdg and tdg as its phase gate r(-pi/2) and r(-pi/4)); any other statement
// stops the script. The gates are exact up to floating point except for jsqubits' rounding of amplitudes
// below QState.roundToZero to zero, set here to 1e-13 (its default, 1e-7, would drop amplitudes whose
// probability is up to 1e-14; 1e-13 is above the residue of exact cancellations, about 1e-16, which
// would otherwise stay in the sparse state as entries). jsqubits builds its bit masks with 32-bit
// shifts, so a file may have at most 31 qubits. With --serve it checks many files in one process (check-serve.mjs).

import Qubits from "jsqubits";
import { readMeasuredRegister, registerDistribution } from "./qasm2-measured-register.mjs";
import { runCheck, UsageError } from "./check-serve.mjs";

Qubits.QState.roundToZero = 1e-13;

const gates = {
  x: (s, [a]) => s.x(a),
  y: (s, [a]) => s.y(a),
  z: (s, [a]) => s.z(a),
  h: (s, [a]) => s.hadamard(a),
  s: (s, [a]) => s.s(a),
  sdg: (s, [a]) => s.r(a, -Math.PI / 2),
  t: (s, [a]) => s.t(a),
  tdg: (s, [a]) => s.r(a, -Math.PI / 4),
  cx: (s, [a, b]) => s.controlledX(a, b),
  cy: (s, [a, b]) => s.controlledY(a, b),
  cz: (s, [a, b]) => s.controlledZ(a, b),
  ccx: (s, [a, b, c]) => s.controlledX([a, b], c),
  swap: (s, [a, b]) => s.swap(a, b),
  rx: (s, [a], angle) => s.rotateX(a, angle),
  ry: (s, [a], angle) => s.rotateY(a, angle),
  rz: (s, [a], angle) => s.rotateZ(a, angle),
};

/** The reply for one file. */
function check([file]) {
  if (!file) throw new UsageError();
  const { kept, register, measured } = readMeasuredRegister(file);
  let state = null;
  for (const line of kept) {
    const text = line.trim();
    if (text === "" || text.startsWith("//") || text === "OPENQASM 2.0;" || text === 'include "qelib1.inc";' || /^creg \w+\[\d+\];$/.test(text)) continue;
    const qreg = text.match(/^qreg q\[(\d+)\];$/);
    if (qreg) {
      const qubits = Number(qreg[1]);
      if (state !== null || qubits > 31) throw new Error(`jsqubits holds one register of at most 31 qubits: ${text}`);
      state = Qubits("0".repeat(qubits));
      continue;
    }
    const m = text.match(/^(\w+)(?:\(([-+0-9.eE]+)\))? (q\[\d+\](?:, q\[\d+\])*);$/);
    if (!m || !(m[1] in gates) || state === null) throw new Error(`not a gate statement this check reads: ${text}`);
    const operands = [...m[3].matchAll(/q\[(\d+)\]/g)].map((q) => Number(q[1]));
    state = gates[m[1]](state, operands, m[2] === undefined ? undefined : Number(m[2]));
  }

  const amplitudes = [];
  state.each((c) => amplitudes.push([c.asNumber(), c.amplitude.real, c.amplitude.imaginary]));
  return { register, bits: measured.length, qubits: state.numBits(), probabilities: registerDistribution(amplitudes, measured) };
}

await runCheck("node check-openqasm-jsqubits.mjs FILE | --serve", check);
