// Which Pauli errors can harm a circuit at each of its noise locations (one per qubit an operation touches, after the
// operation; a measurement's before it), as the QDK's noisy simulator places them. Counted per gate kind and per
// pattern of harmful Paulis: { kind: { "XYZ": n, "XY": n, "YZ": n, "": n, … } }.
//
// The state is tracked classically as branches: each qubit holds its value as a truth table over "sources", the
// qubits put into superposition (H, Ry, … on a qubit in a basis state, or on a qubit that is one source alone and that
// nothing else depends on, as the diffusion's H gates on the index register are). X, CX and CCX act on the tables;
// diagonal gates leave them. A superposing gate on a qubit entangled with others (the H of a measurement-based
// uncomputation) leaves it "tainted" until it is measured or reset. The tables track the support of the state, not its
// amplitudes, so every judgement below errs towards harmful.
//
// Rules, per location of qubit q:
//   any Pauli   harmless when q's next operation is a reset (the error is discarded);
//   Z           harmless when q is in a computational basis state there (the same bit on every branch: a Z only
//               multiplies the state by ±1), or when the Z reaches a measurement or reset through nothing but
//               diagonal gates and control roles (it commutes with them, and a measurement in the computational
//               basis does not see it); otherwise harmful;
//   X           followed through the rest of the circuit as a flipped bit on every branch, beside the error-free
//               run: harmless when the difference dies out (uncomputed), ends as the same flip on every branch of a
//               qubit no later operation reads (a product state), or reaches the H of a measurement-based
//               uncomputation as such a flip (it turns into a Z, which the measurement does not see); harmful when
//               it changes a phase on some branches and not on others, a measured value, an index qubit at the
//               diffusion's H, or meets a tainted qubit;
//   Y           harmful when X or Z is (Y = iXZ).

export const diagonal = new Set(["Z", "S", "T", "Rz", "R1", "I"]);

export class Tracker {
  constructor(branches, maxSources) {
    this.branches = branches;
    this.maxSources = maxSources;
    this.values = new Map(); // qubit -> Uint8Array(branches), the qubit's bit on each branch
    this.tainted = new Set();
    this.sources = 0;
  }

  clone() {
    const copy = new Tracker(this.branches, this.maxSources);
    for (const [q, v] of this.values) copy.values.set(q, v.slice());
    copy.tainted = new Set(this.tainted);
    copy.sources = this.sources;
    return copy;
  }

  value(q) {
    let v = this.values.get(q);
    if (!v) this.values.set(q, (v = new Uint8Array(this.branches)));
    return v;
  }

  isBasis(q) {
    if (this.tainted.has(q)) return false;
    const v = this.value(q);
    for (let b = 1; b < this.branches; b++) if (v[b] !== v[0]) return false;
    return true;
  }

  // Whether q holds one source alone whose copies other (untainted) qubits still hold: an H on q now would taint it.
  entangledCopies(q) {
    if (this.tainted.has(q) || this.isBasis(q)) return false;
    const s = this.loneSource(q);
    return s >= 0 && [...this.values.keys()].some((o) => o !== q && !this.tainted.has(o) && this.dependsOn(o, s));
  }

  // The source s when q's table is s or its complement, else -1.
  loneSource(q) {
    const v = this.value(q);
    for (let s = 0; s < this.sources; s++) {
      let same = v[0] !== v[1 << s];
      for (let b = 0; b < this.branches && same; b++) same = v[b] === (((b >> s) & 1) ^ v[0]);
      if (same) return s;
    }
    return -1;
  }

  dependsOn(q, s) {
    const v = this.value(q);
    for (let b = 0; b < this.branches; b++) if (v[b] !== v[b ^ (1 << s)]) return true;
    return false;
  }

  collapse(q) {
    this.values.set(q, new Uint8Array(this.branches));
    this.tainted.delete(q);
  }

  superpose(q, controls) {
    const controlled = controls.some((c) => !this.isBasis(c));
    if (this.isBasis(q) && this.sources < this.maxSources) return this.fresh(q); // with controls, the support over-approximated
    const s = this.loneSource(q);
    // A tainted qubit's table is stale (it is awaiting the measurement of a measurement-based uncomputation, which commutes
    // with this gate), so it does not count as depending on s: else the trace's column order, not the circuit, would decide.
    if (s >= 0 && !controlled && ![...this.values.keys()].some((o) => o !== q && !this.tainted.has(o) && this.dependsOn(o, s))) return;
    this.tainted.add(q);
  }

  fresh(q) {
    const s = this.sources++;
    const v = new Uint8Array(this.branches);
    if (s < 30) for (let b = 0; b < this.branches; b++) v[b] = (b >> s) & 1;
    this.values.set(q, v);
    this.tainted.delete(q);
  }

  flip(target, controls) {
    if (controls.some((c) => this.tainted.has(c))) {
      this.tainted.add(target);
      return;
    }
    const t = this.value(target);
    const cs = controls.map((c) => this.value(c));
    for (let b = 0; b < this.branches; b++) {
      let on = 1;
      for (const c of cs) on &= c[b];
      t[b] ^= on;
    }
  }

  apply(op) {
    if (op.reset || op.measurement) {
      for (const q of op.qubits) this.collapse(q);
    } else if (diagonal.has(op.gate)) {
      // A phase: the tables stay.
    } else if (op.gate === "X") {
      for (const t of op.targets) this.flip(t, op.controls);
    } else if (op.gate === "SWAP") {
      const [a, b] = op.targets; // three CX (CCX under a control)
      this.flip(a, [...op.controls, b]);
      this.flip(b, [...op.controls, a]);
      this.flip(a, [...op.controls, b]);
    } else {
      for (const t of op.targets) this.superpose(t, op.controls);
    }
  }
}

export function differs(a, b) {
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return true;
  return false;
}

// Whether the branchwise difference of two tables is the same on every branch (nothing, or a flip everywhere).
export function uniformDifference(a, b) {
  const d = a[0] ^ b[0];
  for (let i = 1; i < a.length; i++) if ((a[i] ^ b[i]) !== d) return false;
  return true;
}

export function product(tracker, qubits) {
  const out = new Uint8Array(tracker.branches).fill(1);
  for (const q of qubits) {
    const v = tracker.value(q);
    for (let b = 0; b < out.length; b++) out[b] &= v[b];
  }
  return out;
}

/** A superposing gate whose dirty targets the caller has judged: both runs take the error-free run's targets after it. */
export function superposeBoth(clean, faulty, op, dirty) {
  clean.apply(op);
  for (const t of op.targets) {
    faulty.values.set(t, clean.value(t).slice());
    if (clean.tainted.has(t)) faulty.tainted.add(t);
    dirty.delete(t);
  }
  faulty.sources = clean.sources;
}

/** Applies `op` to the error-free and the faulty run and updates which of its qubits differ. */
export function applyBoth(clean, faulty, op, dirty) {
  clean.apply(op);
  faulty.apply(op);
  for (const x of op.qubits) {
    if (differs(clean.value(x), faulty.value(x))) dirty.add(x);
    else dirty.delete(x);
  }
}

/**
 * The operations in an order the tracker can read: the QDK lays a trace out in columns, each gate as early as its qubits
 * allow, so a diffusion's H on an index qubit can be listed before the oracle's uncomputation of that qubit's copies on other
 * qubits (which commutes with it). Tracked in that order, the H would meet a register still entangled and leave it tainted
 * for the rest of the circuit. Here such an H, and every later operation on its qubits, waits until nothing else depends on
 * its qubit; each qubit keeps its own order, so the circuit is the same. An H that still waits after `patience` operations
 * goes ahead (the tracker then taints it, as without the reordering).
 */
export function trackableOrder(ops, patience = 256) {
  const sources = sourcesOf(ops);
  const tracker = new Tracker(1 << sources, sources);
  const ordered = [];
  let waiting = [];
  const blocked = new Set();
  const waits = (op) => op.gate === "H" && op.controls.length === 0 && op.targets.length === 1 && tracker.entangledCopies(op.targets[0]);
  const release = (force) => {
    for (let changed = true; changed && waiting.length > 0;) {
      changed = false;
      blocked.clear();
      const still = [];
      for (const op of waiting) {
        if (op.qubits.some((q) => blocked.has(q)) || (!force && waits(op))) {
          still.push(op);
          for (const q of op.qubits) blocked.add(q);
        } else {
          tracker.apply(op);
          ordered.push(op);
          changed = true;
        }
      }
      waiting = still;
    }
  };
  for (const op of ops) {
    if (op.qubits.some((q) => blocked.has(q)) || (!op.measurement && !op.reset && waits(op))) {
      waiting.push(op);
      for (const q of op.qubits) blocked.add(q);
      if (waiting.length > patience) release(true);
      continue;
    }
    tracker.apply(op);
    ordered.push(op);
    if (waiting.length > 0) release(false);
  }
  release(true);
  return ordered;
}

/** The number of sources (superposed qubits) the circuit creates, at least 1, for sizing the tables. */
function sourcesOf(ops) {
  const probe = new Tracker(1 << 10, 10);
  for (const op of ops) probe.apply(op);
  return Math.max(1, probe.sources);
}

const checkpointEvery = 32;

export class Circuit {
  constructor(ops) {
    this.ops = ops;
    const sources = sourcesOf(ops);
    this.checkpoints = [];
    const tracker = new Tracker(1 << sources, sources);
    this.basis = ops.map((op, k) => {
      if (k % checkpointEvery === 0) this.checkpoints.push(tracker.clone());
      const before = op.measurement ? op.qubits.map((q) => tracker.isBasis(q)) : null;
      tracker.apply(op);
      return before ?? op.qubits.map((q) => tracker.isBasis(q));
    });
    // Each operation's next operation on each of its qubits (ops.length: none).
    const following = new Map();
    this.next = new Array(ops.length);
    for (let k = ops.length - 1; k >= 0; k--) {
      this.next[k] = ops[k].qubits.map((q) => following.get(q) ?? ops.length);
      for (const q of ops[k].qubits) following.set(q, k);
    }
  }

  // The error-free state just after operation k.
  stateAfter(k) {
    const start = Math.floor(k / checkpointEvery) * checkpointEvery;
    const tracker = this.checkpoints[start / checkpointEvery].clone();
    for (let m = start; m <= k; m++) tracker.apply(this.ops[m]);
    return tracker;
  }

  nextOn(k, q) {
    return this.next[k][this.ops[k].qubits.indexOf(q)];
  }

  // Whether an X on qubit q just after gate k can harm the run.
  xHarms(k, q) {
    const clean = this.stateAfter(k);
    if (clean.tainted.has(q)) return true;
    const faulty = clean.clone();
    faulty.flip(q, []);
    const dirty = new Set([q]);
    for (let m = k + 1; m < this.ops.length && dirty.size > 0; m++) {
      const op = this.ops[m];
      const touched = op.qubits.some((x) => dirty.has(x));
      if (!touched) {
        clean.apply(op);
        faulty.apply(op);
        continue;
      }
      if (op.reset) {
        for (const x of op.qubits) dirty.delete(x);
      } else if (op.measurement) {
        return true;
      } else if (diagonal.has(op.gate)) {
        if (!uniformDifference(product(clean, op.qubits), product(faulty, op.qubits))) return true;
      } else if (op.gate === "X" || op.gate === "SWAP") {
        if (op.qubits.some((x) => clean.tainted.has(x) || faulty.tainted.has(x))) return true;
      } else {
        for (const t of op.targets) {
          if (!dirty.has(t)) continue;
          // A flip on every branch before the H of a measurement-based uncomputation becomes a Z the measurement does not see.
          const measuredNext = this.ops[this.nextOn(m, t)]?.measurement || this.ops[this.nextOn(m, t)]?.reset;
          if (!(measuredNext && uniformDifference(clean.value(t), faulty.value(t)))) return true;
        }
        if (op.controls.some((c) => dirty.has(c))) return true;
        superposeBoth(clean, faulty, op, dirty);
        continue;
      }
      applyBoth(clean, faulty, op, dirty);
    }
    // What is left is harmless only as the same flip on every branch (a product state).
    for (const x of dirty) if (!uniformDifference(clean.value(x), faulty.value(x))) return true;
    return false;
  }
}

/** The operations' noise exposure. `ops` are { kind, gate, qubits, controls, targets, measurement, reset } in order. */
export function noiseExposure(ops, circuit = new Circuit(ops), patterns = locationPatterns(ops, circuit)) {
  const exposure = {};
  for (const { kind, pattern } of patterns) {
    const tally = (exposure[kind] ??= {});
    tally[pattern] = (tally[pattern] ?? 0) + 1;
  }
  return exposure;
}

/** Every noise location (op k, qubit q, the op's kind) with the pattern of Paulis harmful there, last operation first. */
export function locationPatterns(ops, circuit) {
  const found = [];
  // Backward, for Z: whether a Z just after the current point reaches a measurement or reset ("readout") or a reset
  // next ("reset"), through diagonal gates and control roles only.
  const zPath = new Map();
  for (let k = ops.length - 1; k >= 0; k--) {
    const op = ops[k];
    if (op.reset) {
      for (const q of op.qubits) zPath.set(q, "reset");
      continue;
    }
    op.qubits.forEach((q, j) => {
      const after = op.measurement ? "readout" : zPath.get(q) ?? "readout";
      let pattern;
      if (after === "reset") pattern = "";
      else {
        const z = after !== "readout" && !circuit.basis[k][j];
        const x = op.measurement ? true : circuit.xHarms(k, q);
        pattern = (x ? "X" : "") + (x || z ? "Y" : "") + (z ? "Z" : "");
      }
      found.push({ k, q, kind: op.kind, pattern });
      const commutes = op.controls?.includes(q) || diagonal.has(op.gate);
      zPath.set(q, op.measurement ? "readout" : commutes ? (after === "reset" ? "readout" : after) : "other");
    });
  }
  return found;
}
