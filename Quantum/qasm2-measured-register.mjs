// Splits an OpenQASM 2.0 file as `qrt export --format qasm2` writes it into the statements before its final
// measurements and the measured register (its name and the qubit -> register bit map), and sums a
// simulator's final amplitudes into that register's exact distribution. The check scripts use it to read
// a file the same way whichever simulator runs it.

import fs from "node:fs";

/** { kept: the lines before the measurements, register, measured: [[qubit, bit], ...] } of FILE. */
export function readMeasuredRegister(file) {
  const lines = fs.readFileSync(file, "utf8").split("\n");
  const measured = [];
  const kept = [];
  let register = null;
  for (const line of lines) {
    const m = line.match(/^\s*measure\s+q\[(\d+)\]\s*->\s*(\w+)\[(\d+)\]\s*;\s*$/);
    if (m) {
      if (register !== null && m[2] !== register) throw new Error("the measurements fill more than one register");
      register = m[2];
      measured.push([Number(m[1]), Number(m[3])]);
    } else if (measured.length > 0 && line.trim() !== "") throw new Error(`a statement follows the measurements: ${line}`);
    else kept.push(line);
  }
  if (measured.length === 0) throw new Error("the file measures nothing");
  return { kept, register, measured };
}

/** The register's distribution from [basis index, re, im] entries (qubit k is bit k of the index). */
export function registerDistribution(amplitudes, measured) {
  const probabilities = {};
  for (const [index, re, im] of amplitudes) {
    let value = 0;
    for (const [qubit, bit] of measured) if (Math.floor(index / 2 ** qubit) % 2 === 1) value += 2 ** bit;
    probabilities[value] = (probabilities[value] ?? 0) + re * re + im * im;
  }
  return probabilities;
}
