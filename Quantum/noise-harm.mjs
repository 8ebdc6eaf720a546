// How much each Pauli error harms a Grover run, graded by what it does to the run's success probability.
// Per gate kind, the summed harm of X, Y and Z over the kind's noise locations: { kind: { X: h, Y: h, Z: h } }, with
// h = (P₀ − P_e) / (P₀ − u) for an error whose only effect is a known phase on the index branches (P₀ the error-free
// P(marked), P_e with that error alone, u the uniform register's), and h = 1 where the counting rule of noise-exposure.mjs
// calls the Pauli harmful and its effect is anything else. With Φ = Π (1 − p)^h over locations and Paulis, the global
// depolarizing form Φ · P₀ + (1 − Φ) · u then agrees with the circuit to first order in p.
//
// Why a phase: between two diffusions (the "oracle section", every index qubit in the computational basis) each branch
// (one index value) carries every other qubit in a basis state, so a Z on a qubit holding the table f multiplies branch b
// by (−1)^f(b), and an X whose flipped bit changes the oracle's diagonal gates on some branches and is then uncomputed does
// the same with the table of those changes. Such a phase commutes with the whole section: it is the section's oracle with
// some branches' signs flipped. After the last diffusion it changes nothing the measurement sees; in the first section it
// can unmark the marked index or mark others, which costs a run more or less than the uniform readout, by how many.
// The tables track the support of the state, not its amplitudes; the index register's amplitudes are simulated exactly
// (2^n values, the oracle's marking read from its diagonal gates). Negative harm (an error that helps) is counted as none.
//
// Beside the harm, `channels` gives the same errors per iteration as channels on the index register, for a model in which
// several errors need not harm independently (Host/Noise/SearchChannels.cs): the whole harm of the effects graded FULL, and
// the dephasing of the others, averaged over each class of index pairs (pairClasses).

import { applyBoth, Circuit, diagonal, locationPatterns, product, superposeBoth, uniformDifference } from "./noise-exposure.mjs";

/**
 * The graded harm of `ops` (as noise-exposure.mjs takes them), a search for `marked` (its marked indices; empty or null: read
 * from the oracle's diagonal gates); null where the circuit is not read as a Grover search over its index register.
 * Returns { harm, outsideHarm, sections, sampling }: `harm` per gate kind and Pauli over every location, `outsideHarm` the part
 * at the preparation's H and the index register's final measurement (always graded whole), `sections` the oracle sections
 * found (the Grover iterations), and `sampling` { fraction, graded, variance }. With `fraction` < 1 each other location is
 * graded with that probability (a generator seeded by `seed`) and weighted 1 / fraction, so `harm` is an unbiased estimate of
 * the whole grading; `variance` is the estimate's variance in harm-weighted locations (a third of each Pauli's h, summed),
 * estimated from the graded locations (0 when every location is graded).
 */
export function gradedHarm(ops, marked = null, circuit = new Circuit(ops), { fraction = 1, seed = 1, patterns = locationPatterns(ops, circuit) } = {}) {
  if (!(fraction > 0 && fraction <= 1)) throw new Error(`the sampled fraction must lie in (0, 1], not ${fraction}`);
  const { rewritten, conjugated } = phaseGates(ops);
  const search = new SearchStructure(rewritten, new Circuit(rewritten), marked);
  if (!search.graded) return null;
  const harm = {};
  const outsideHarm = {};
  // The iterations' errors as channels on the index register (pairClasses below), per iteration: the whole harm of the effects
  // graded FULL at its locations (a diffusion's with its oracle section, those after the last diffusion with the last), and the
  // class-averaged dephasing of the errors whose effect is a known phase or garbage in its oracle section.
  const fullHarm = Array.from({ length: search.iterations }, () => ({ X: 0, Y: 0, Z: 0 }));
  const dephasing = Array.from({ length: search.iterations }, () => ({ X: pairClasses(), Y: pairClasses(), Z: pairClasses() }));
  const random = seededUniform(seed);
  let graded = 0;
  let variance = 0;
  for (const { k, q, kind, pattern } of patterns) {
    const tally = (harm[kind] ??= { X: 0, Y: 0, Z: 0 });
    if (pattern === "") continue;
    const outside = search.outside.has(`${k}:${q}`);
    const weight = outside || fraction === 1 ? 1 : random() < fraction ? 1 / fraction : 0;
    if (weight === 0) continue;
    graded++;
    const effects = locationEffects(search, conjugated, k, q, pattern);
    const h = { X: search.harmOf(effects.X), Y: search.harmOf(effects.Y), Z: search.harmOf(effects.Z) };
    if (!outside) {
      for (const pauli of ["X", "Y", "Z"]) {
        const effect = effects[pauli];
        if (effect.full) fullHarm[search.iterationOf[k] - 1][pauli] += weight;
        else if (effect.branches.some((b) => b.phase || b.garbage)) {
          const section = effect.branches.find((b) => b.phase || b.garbage).section;
          if (section >= 1 && section <= search.iterations) addPairClasses(dephasing[section - 1][pauli], search.pairDephasing(effect), weight);
        }
      }
    }
    tally.X += weight * h.X;
    tally.Y += weight * h.Y;
    tally.Z += weight * h.Z;
    // Bernoulli sampling: Var(Σ w·h) = Σ (1 − f) / f² · h², estimated without bias by Σ over the graded of (1 − f) / f² · h².
    if (weight > 1) variance += ((1 - fraction) / (fraction * fraction)) * ((h.X + h.Y + h.Z) / 3) ** 2;
    if (outside) {
      const part = (outsideHarm[kind] ??= { X: 0, Y: 0, Z: 0 });
      part.X += h.X;
      part.Y += h.Y;
      part.Z += h.Z;
    }
  }
  const channels = { fullHarm, dephasing, marked: search.markedCount, register: search.marked.length };
  return { harm, outsideHarm, sections: search.iterations, sampling: { fraction, graded, variance }, channels };
}

/** The effects of X, Y and Z at op k's location on qubit q, whose harmful Paulis the counting rule gives as `pattern`. */
function locationEffects(search, conjugated, k, q, pattern) {
  if (conjugated.has(`${k}:${q}`)) {
    // Between the H gates of a controlled phase the target is in the Hadamard basis: counted by the rule alone.
    return { X: pattern.includes("X") ? FULL : NONE, Y: FULL, Z: pattern.includes("Z") ? FULL : NONE };
  }
  const x = pattern.includes("X") ? search.xEffect(k, q) : NONE;
  const z = pattern.includes("Z") ? search.zEffect(k, q) : NONE;
  return { X: x, Y: combine(x, z), Z: z };
}

// The dephasing an error leaves between two index branches b and b': with the error, their coherence is multiplied by
// E = Σ over the effect's branches of weight · σ(b) σ(b') · [same garbage], so at rate q it is multiplied by 1 − q · (1 − E).
// Summed over locations per pair class (marked with unmarked, two unmarked, two marked) and averaged within the class: the
// rate of that class's coherence decay per unit of the Pauli's probability.
function pairClasses() {
  return { cross: 0, unmarked: 0, marked: 0 };
}

function addPairClasses(into, rates, weight) {
  into.cross += weight * rates.cross;
  into.unmarked += weight * rates.unmarked;
  into.marked += weight * rates.marked;
}

/** Uniform numbers in [0, 1) from a 32-bit seed (mulberry32): the sampled locations are the same for the same seed and circuit. */
function seededUniform(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/**
 * The operations with each H · (multi-)controlled X · H on one target (the next operations on it) read as the controlled
 * Z it is, the H gates as identities; and the locations of that target inside the H gates ("k:q").
 */
function phaseGates(ops) {
  const rewritten = ops.slice();
  const conjugated = new Set();
  const next = new Map();
  const following = new Array(ops.length);
  for (let k = ops.length - 1; k >= 0; k--) {
    following[k] = new Map(ops[k].qubits.map((q) => [q, next.get(q)]));
    for (const q of ops[k].qubits) next.set(q, k);
  }
  ops.forEach((op, k) => {
    if (op.gate !== "H" || op.controls.length > 0 || op.targets.length !== 1 || rewritten[k] !== op) return;
    const t = op.targets[0];
    const x = following[k].get(t);
    const flip = ops[x];
    if (!flip || flip.gate !== "X" || flip.controls.length === 0 || flip.targets.length !== 1 || flip.targets[0] !== t) return;
    const h = following[x].get(t);
    if (ops[h]?.gate !== "H" || ops[h].controls.length > 0) return;
    rewritten[k] = { ...op, gate: "I" };
    rewritten[x] = { ...flip, gate: "Z", conjugated: true };
    rewritten[h] = { ...ops[h], gate: "I" };
    conjugated.add(`${k}:${t}`);
    conjugated.add(`${x}:${t}`);
  });
  return { rewritten, conjugated };
}

// An error's effect: FULL (harm 1), or the branches it leaves with their weights, each a phase on the index branches in
// one oracle section or none: a flipped bit that reaches a measurement-based uncomputation's correction leaves that
// correction's mismatch with probability ½ (the outcome is random). More than `maxBranches` count as FULL.
const FULL = { full: true };
const NONE = { branches: [{ weight: 1, section: 0, phase: null }] };
const maxBranches = 16;

function phaseEffect(section, phase) {
  return { branches: [{ weight: 1, section, phase }] };
}

function combine(a, b) {
  if (a.full || b.full) return FULL;
  const branches = [];
  for (const x of a.branches) {
    for (const y of b.branches) {
      if ((x.phase || x.garbage) && (y.phase || y.garbage) && x.section !== y.section) return FULL;
      const phase = x.phase && y.phase ? x.phase.map((v, i) => v ^ y.phase[i]) : x.phase ?? y.phase;
      if (x.garbage && y.garbage) return FULL;
      branches.push({ weight: x.weight * y.weight, section: x.phase || x.garbage ? x.section : y.section, phase, garbage: x.garbage ?? y.garbage });
    }
  }
  return branches.length > maxBranches ? FULL : { branches };
}

/** Half the time `effect`, half the time `effect` with `phase` in `section` too. */
function halfWith(effect, section, phase) {
  return combine(effect, { branches: [{ weight: 0.5, section: 0, phase: null }, { weight: 0.5, section, phase }] });
}

class SearchStructure {
  constructor(ops, circuit, marked) {
    this.ops = ops;
    this.circuit = circuit;
    // The index register: the qubits whose first operation is an H (the preparation) and whose last but resets a measurement.
    const first = new Map();
    const last = new Map();
    ops.forEach((op, k) => {
      for (const q of op.qubits) {
        if (!first.has(q)) first.set(q, k);
        if (!op.reset) last.set(q, k);
      }
    });
    const index = new Set([...first].filter(([q, k]) => ops[k].gate === "H" && ops[k].controls.length === 0 && ops[last.get(q)].measurement).map(([q]) => q));
    // Outside the iterations: each index qubit's preparing H and its final measurement (locations "op:qubit").
    this.outside = new Set([...index].flatMap((q) => [`${first.get(q)}:${q}`, `${last.get(q)}:${q}`]));
    const tracker = circuit.checkpoints[0].clone();
    const parity = new Map();
    this.indexSources = [];
    this.section = new Int32Array(ops.length); // after op k: the oracle section (1 before the first diffusion), or −1 inside a diffusion
    this.sectionBefore = new Int32Array(ops.length);
    this.correctionOf = new Map(); // a measurement-based uncomputation's phase correction (op) -> its target's uncomputing H (op)
    this.correctionTarget = new Map(); // that correction (op) -> the target
    this.preHadamard = new Map(); // an uncomputing H (op) -> the target's table before it
    this.uncomputePhase = new Map(); // an uncomputing measurement (op) -> the phase a flipped outcome leaves (the target's table)
    // An uncomputing H: one whose target's next operation is a measurement. Per qubit and generation (resets), its op.
    const uncomputing = new Map();
    {
      const generation = new Map();
      ops.forEach((op, k) => {
        if (op.reset) for (const q of op.qubits) generation.set(q, (generation.get(q) ?? 0) + 1);
        if (op.gate === "H" && op.controls.length === 0 && op.targets.length === 1) {
          const t = op.targets[0];
          if (!index.has(t) && ops[circuit.nextOn(k, t)]?.measurement) uncomputing.set(`${t}:${generation.get(t) ?? 0}`, k);
        }
      });
    }
    {
      // The table each uncomputing H's target holds before it, for corrections listed before their H.
      const ahead = tracker.clone();
      const seen = new Map();
      ops.forEach((op, k) => {
        if (op.gate === "H" && op.controls.length === 0 && op.targets.length === 1) {
          const t = op.targets[0];
          if (uncomputing.get(`${t}:${seen.get(t) ?? 0}`) === k) this.preHadamard.set(k, ahead.value(t).slice());
        }
        if (op.reset) for (const q of op.qubits) seen.set(q, (seen.get(q) ?? 0) + 1);
        ahead.apply(op);
      });
    }
    const generation = new Map();
    const corrected = new Set(); // uncomputing H ops whose correction was found
    const oracle = new Map(); // section -> the oracle's diagonal gates' products, over all branches
    let section = 1;
    let inside = false;
    this.graded = index.size > 0;
    ops.forEach((op, k) => {
      this.sectionBefore[k] = inside ? -1 : section;
      if (op.gate === "H" && op.controls.length === 0) {
        for (const q of op.targets) {
          if (index.has(q)) {
            if (tracker.isBasis(q)) this.indexSources.push(tracker.sources);
            else parity.set(q, (parity.get(q) ?? 0) ^ 1);
          }
        }
      }
      if (op.measurement) {
        for (const q of op.qubits) {
          const h = uncomputing.get(`${q}:${generation.get(q) ?? 0}`);
          if (h !== undefined && this.preHadamard.has(h)) this.uncomputePhase.set(k, this.preHadamard.get(h));
        }
      }
      if (!op.measurement && !op.reset && diagonal.has(op.gate)) {
        // The correction of a qubit measured out after an H: a Z, CZ, … whose product is the table the qubit held before the H.
        const table = product(tracker, op.qubits);
        let match;
        if (!op.conjugated) {
          for (const [key, h] of uncomputing) {
            const [t, g] = key.split(":").map(Number);
            if (corrected.has(h) || (generation.get(t) ?? 0) !== g || op.qubits.includes(t)) continue;
            const measured = this.preHadamard.get(h);
            if (uniformDifference(measured, table)) { // equal, or complementary: the same phase up to a global sign
              match = [t, h];
              break;
            }
          }
        }
        if (match) {
          corrected.add(match[1]);
          this.correctionTarget.set(k, match[0]);
          this.correctionOf.set(k, match[1]);
        } else if (!inside) {
          const acc = oracle.get(section) ?? new Uint8Array(table.length);
          for (let b = 0; b < table.length; b++) acc[b] ^= table[b];
          oracle.set(section, acc);
        }
      }
      if (op.reset) for (const q of op.qubits) generation.set(q, (generation.get(q) ?? 0) + 1);
      tracker.apply(op);
      const nowInside = [...parity.values()].some((v) => v === 1);
      if (inside && !nowInside) section++;
      inside = nowInside;
      this.section[k] = inside ? -1 : section;
    });
    this.iterations = section - 1;
    // The iteration each op belongs to: the last oracle section begun at or before it, at most the last iteration.
    this.iterationOf = new Int32Array(ops.length);
    let owner = 1;
    for (let k = 0; k < ops.length; k++) {
      if (this.sectionBefore[k] > 0) owner = this.sectionBefore[k];
      this.iterationOf[k] = Math.max(1, Math.min(owner, this.iterations));
    }
    this.n = this.indexSources.length;
    this.graded &&= this.n === index.size && this.n > 0 && this.iterations > 0;
    if (!this.graded) return;
    if (marked?.length > 0) {
      // The marked indices as the request gives them: index qubit j (the j-th the preparation superposes) is bit j.
      this.marked = new Uint8Array(1 << this.n);
      for (const i of marked) if (i >= 0 && i < this.marked.length) this.marked[i] = 1;
    } else {
      // The marking read from the oracle sections' diagonal gates, the same in every section.
      const first = this.indexPattern(oracle.get(1) ?? new Uint8Array(circuit.checkpoints[0].branches));
      for (let j = 2; j <= this.iterations && first; j++) {
        const other = this.indexPattern(oracle.get(j) ?? new Uint8Array(first.length));
        if (!other || other.some((v, i) => v !== first[i])) this.graded = false;
      }
      if (!first) this.graded = false;
      if (!this.graded) return;
      const ones = first.reduce((sum, v) => sum + v, 0);
      this.marked = ones * 2 > first.length ? first.map((v) => v ^ 1) : first;
    }
    this.markedCount = this.marked.reduce((s, v) => s + v, 0);
    this.cache = new Map();
    this.pairCache = new Map();
    this.clean = this.success(0, null);
    this.uniform = this.markedCount / this.marked.length;
  }

  /** A table over all branches as a table over the index branches; null when it depends on another source. */
  indexPattern(table) {
    const out = new Uint8Array(1 << this.n);
    const full = table.length;
    for (let b = 0; b < full; b++) {
      let i = 0;
      this.indexSources.forEach((s, j) => { i |= ((b >> s) & 1) << j; });
      if (b === this.branchOf(i)) out[i] = table[b];
      else if (table[b] !== table[this.branchOf(i)]) return null;
    }
    return out;
  }

  branchOf(i) {
    let b = 0;
    this.indexSources.forEach((s, j) => { b |= ((i >> j) & 1) << s; });
    return b;
  }

  /**
   * P(marked) of the run with `phase` (or none) multiplying the oracle of `section`, and from that section's diffusion on,
   * the branches split by `garbage` (a value per index branch left on qubits no later operation undoes): branches with
   * different garbage no longer interfere.
   */
  success(section, phase, garbage = null) {
    const size = this.marked.length;
    let vectors = [new Float64Array(size).fill(1 / Math.sqrt(size))];
    for (let j = 1; j <= this.iterations; j++) {
      for (const a of vectors) for (let b = 0; b < size; b++) if (this.marked[b] ^ (j === section && phase ? phase[b] : 0)) a[b] = -a[b];
      if (j === section && garbage) {
        const classes = new Map();
        for (let b = 0; b < size; b++) {
          if (!classes.has(garbage[b])) classes.set(garbage[b], new Float64Array(size));
          classes.get(garbage[b])[b] = vectors[0][b];
        }
        vectors = [...classes.values()];
      }
      vectors = vectors.map((a) => {
        const mean = a.reduce((sum, v) => sum + v, 0) / size;
        return a.map((v) => 2 * mean - v);
      });
    }
    let p = 0;
    for (const a of vectors) for (let b = 0; b < size; b++) if (this.marked[b]) p += a[b] * a[b];
    return p;
  }

  /** The class-averaged 1 − E of an effect's branches over the index register's pairs (see pairClasses). */
  pairDephasing(effect) {
    const key = effect.branches.map((b) => `${b.weight}:${b.phase?.join("")}:${b.garbage?.join(",")}`).join("|");
    let rates = this.pairCache.get(key);
    if (rates) return rates;
    const size = this.marked.length;
    const sums = pairClasses();
    const counts = pairClasses();
    for (let a = 0; a < size; a++) {
      for (let b = a + 1; b < size; b++) {
        let kept = 0;
        for (const branch of effect.branches) {
          if (branch.garbage && branch.garbage[a] !== branch.garbage[b]) continue;
          const flipped = branch.phase ? branch.phase[a] ^ branch.phase[b] : 0;
          kept += branch.weight * (flipped ? -1 : 1);
        }
        const cls = this.marked[a] && this.marked[b] ? "marked" : this.marked[a] || this.marked[b] ? "cross" : "unmarked";
        sums[cls] += 1 - kept;
        counts[cls]++;
      }
    }
    rates = { cross: counts.cross ? sums.cross / counts.cross : 0, unmarked: counts.unmarked ? sums.unmarked / counts.unmarked : 0, marked: counts.marked ? sums.marked / counts.marked : 0 };
    this.pairCache.set(key, rates);
    return rates;
  }

  harmOf(effect) {
    if (effect.full) return 1;
    if (effect.branches.every((b) => !b.phase && !b.garbage)) return 0;
    if (!this.graded) return 1;
    return Math.max(0, effect.branches.reduce((sum, b) => sum + b.weight * this.phaseHarm(b.section, b.phase, b.garbage), 0));
  }

  /** (P₀ − P_e) / (P₀ − u) of a run whose oracle in `section` also applies `phase`. */
  phaseHarm(section, phase, garbage = null) {
    const flat = (t) => !t || t.every((v) => v === t[0]);
    if (section > this.iterations || (flat(phase) && flat(garbage))) return 0;
    const key = `${section}:${phase?.join("")}:${garbage?.join(",")}`;
    let h = this.cache.get(key);
    if (h === undefined) {
      const span = this.clean - this.uniform;
      h = span < 1e-9 ? 1 : (this.clean - this.success(section, phase, garbage)) / span;
      this.cache.set(key, h);
    }
    return h;
  }

  /** A Z just after op k on qubit q (the counting rule found it harmful). */
  zEffect(k, q) {
    const section = this.section[k];
    if (!this.graded || section < 0) return FULL;
    const state = this.circuit.stateAfter(k);
    if (state.tainted.has(q)) return FULL;
    const phase = this.indexPattern(state.value(q));
    return phase ? phaseEffect(section, phase) : FULL;
  }

  /** An X just after op k on qubit q, or before it when op k is a measurement (the counting rule found it harmful). */
  xEffect(k, q) {
    if (!this.graded) return FULL;
    const op = this.ops[k];
    if (op.measurement) {
      // A flipped outcome of a measurement-based uncomputation applies the wrong correction: the AND's phase.
      const table = this.uncomputePhase.get(k);
      const section = this.sectionBefore[k];
      if (!table || section < 0) return FULL;
      const phase = this.indexPattern(table);
      return phase ? phaseEffect(section, phase) : FULL;
    }
    const clean = this.circuit.stateAfter(k);
    if (this.preHadamard.has(k) && op.targets[0] === q) {
      // Between an uncomputing H and its measurement an X flips the outcome: the wrong correction, the target's table.
      const phase = this.indexPattern(this.preHadamard.get(k));
      return phase && this.section[k] > 0 ? phaseEffect(this.section[k], phase) : FULL;
    }
    if (clean.tainted.has(q) || this.section[k] < 0) return FULL;
    const faulty = clean.clone();
    faulty.flip(q, []);
    const dirty = new Set([q]);
    const dirtyAtHadamard = new Map(); // an AND target dirty at its uncomputing H -> its faulty table there
    let effect = NONE;
    for (let m = k + 1; m < this.ops.length && dirty.size > 0; m++) {
      const next = this.ops[m];
      if (!next.qubits.some((x) => dirty.has(x))) {
        clean.apply(next);
        faulty.apply(next);
        continue;
      }
      if (next.reset) {
        for (const x of next.qubits) dirty.delete(x);
      } else if (next.measurement) {
        return FULL;
      } else if (this.correctionOf.has(m)) {
        // The uncomputation's outcome is random: it leaves a phase unless the correction matches the AND it measured.
        const target = this.correctionTarget.get(m);
        const h = this.correctionOf.get(m);
        const measured = h === undefined || h > m ? faulty.value(target) : dirtyAtHadamard.get(target) ?? this.preHadamard.get(h);
        const wrong = product(faulty, next.qubits).map((v, i) => v ^ measured[i]);
        if (!uniformDifference(wrong, new Uint8Array(wrong.length))) {
          const phase = this.indexPattern(wrong);
          if (!phase || this.section[m] < 0) return FULL;
          effect = halfWith(effect, this.section[m], phase);
          if (effect.full) return FULL;
        }
      } else if (diagonal.has(next.gate)) {
        const a = product(clean, next.qubits);
        const b = product(faulty, next.qubits);
        if (!uniformDifference(a, b)) {
          if (this.section[m] < 0 || next.gate !== "Z") return FULL;
          const phase = this.indexPattern(a.map((v, i) => v ^ b[i]));
          if (!phase) return FULL;
          effect = combine(effect, phaseEffect(this.section[m], phase));
          if (effect.full) return FULL;
        }
      } else if (next.gate === "X" || next.gate === "SWAP") {
        if (next.qubits.some((x) => clean.tainted.has(x) || faulty.tainted.has(x))) return FULL;
      } else {
        // A superposing gate on a dirty qubit: the counting rule's harmless case only, else the run is harmed.
        for (const t of next.targets) {
          if (!dirty.has(t)) continue;
          if (this.preHadamard.has(m)) {
            dirtyAtHadamard.set(t, faulty.value(t).slice());
            continue;
          }
          const after = this.ops[this.circuit.nextOn(m, t)];
          if (!((after?.measurement || after?.reset) && uniformDifference(clean.value(t), faulty.value(t)))) return FULL;
        }
        if (next.controls.some((c) => dirty.has(c))) return FULL;
        superposeBoth(clean, faulty, next, dirty);
        continue;
      }
      applyBoth(clean, faulty, next, dirty);
    }
    // What is left differs on some branches and not others: garbage that splits the branches from this section's diffusion on.
    const left = [...dirty].filter((x) => !uniformDifference(clean.value(x), faulty.value(x)));
    if (left.length === 0) return effect;
    if (left.length > 20) return FULL;
    const garbage = new Uint32Array(1 << this.n);
    for (const [j, x] of left.entries()) {
      const diff = this.indexPattern(clean.value(x).map((v, i) => v ^ faulty.value(x)[i]));
      if (!diff) return FULL;
      diff.forEach((v, i) => { garbage[i] |= v << j; });
    }
    return combine(effect, { branches: [{ weight: 1, section: this.section[k], phase: null, garbage }] });
  }
}
