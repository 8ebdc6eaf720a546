// The Node bridge between the C# host and the modern QDK (npm package qsharp-lang).
//
//   node bridge.mjs --check   compile the Q# library under src/, alone and with the test operations
//                             under tests/, check that src/ declares every name entry-points.json
//                             lists, and print each diagnostic as
//                             "file(line,col): error QS: message [code]" (exit 1 on any error)
//   node bridge.mjs           compile once, print one "ready" line, then answer requests:
//                             one JSON object per line on stdin, one JSON reply per line on stdout
//
// The bridge loads src/ only; with QRT_QSHARP_TESTS=1 in its environment (the test project sets it)
// it loads tests/ too, the operations only the C# tests call.
//
// Requests carry an "id" that the reply echoes, and a "method":
//   {"id":1,"method":"version"}                               -> {"id":1,"ok":true,"result":{"qsharp":"1.32.5-dev","node":"v20..."}}
//   {"id":2,"method":"run","expr":"Ns.Op(1, [2])","shots":1}  -> {"id":2,"ok":true,"result":["<Q# value of shot 1>", ...]}
//     optional "noise":[px,py,pz] and "qubitLoss":L run the same simulator with Pauli noise and loss (runWithNoise)
//   {"id":3,"method":"estimate","expr":"Ns.Op(8)","params":[{}]} -> {"id":3,"ok":true,"result":[<estimator result per params item>]}
//   {"id":4,"method":"circuit","expr":"Ns.Op(8)","maxOperations":1000000}
//                                                             -> {"id":4,"ok":true,"result":<circuit summary, see circuit-summary.mjs>}
//     optional "exposure":true adds the noise exposure of every location (noise-exposure.mjs); with "harm":true also its
//     graded harm (noise-harm.mjs) for a search marking "marked":[indices] (far slower: it grows as the circuit's square);
//     "harmFraction":f grades a random share f of the locations (seeded by "harmSeed", default 1) for an unbiased estimate
//   {"id":5,"method":"export","apply":"Ns.Op(8, _)","qubits":3,"profile":"adaptive_ri"}
//                                                             -> {"id":5,"ok":true,"result":{"qir":"<QIR text>","probabilities":[p0, p1, ...]}}
//     "apply" is a Qubit[] => Unit expression; optional "measured":M measures the register's first M
//     qubits only (default all); see circuit-export.mjs
// A failure replies {"id":N,"ok":false,"error":{"kind":"qsharp"|"request","message":"...","location":"file:line:col","stack":"..."}}.
// Requests are answered one at a time, in order; simulation runs synchronously inside WebAssembly,
// so the host enforces time limits by killing this process.

import fs from "node:fs";
import path from "node:path";
import readline from "node:readline";
import { fileURLToPath } from "node:url";
import { getCompiler, loadWasmModule, QscEventTarget } from "qsharp-lang";
import { summariseCircuit } from "./circuit-summary.mjs";
import { exportEntryNamespace, exportEntrySource, registerDistribution } from "./circuit-export.mjs";

const projectDir = path.dirname(fileURLToPath(import.meta.url));
const sourceDir = path.join(projectDir, "src");
const testDir = path.join(projectDir, "tests");
const entryPointsFile = path.join(projectDir, "entry-points.json");
const packageDir = path.join(projectDir, "node_modules", "qsharp-lang");

/** Every .qs file under dir, as [path relative to the project, text], in a stable order. */
function readSources(dir) {
  const found = [];
  const walk = (dir) => {
    for (const entry of fs.readdirSync(dir, { withFileTypes: true }).sort((a, b) => a.name.localeCompare(b.name))) {
      const full = path.join(dir, entry.name);
      if (entry.isDirectory()) walk(full);
      else if (entry.name.endsWith(".qs")) found.push([path.relative(projectDir, full).split(path.sep).join("/"), fs.readFileSync(full, "utf8")]);
    }
  };
  walk(dir);
  return found;
}

async function loadCompiler() {
  const wasm = fs.readFileSync(path.join(packageDir, "lib", "web", "qsc_wasm_bg.wasm"));
  await loadWasmModule(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
  return getCompiler();
}

/**
 * Checks all sources as one text (namespaces are explicit, so concatenation is the same program)
 * and maps each diagnostic's line back to the file it came from.
 */
async function checkSources(compiler, sources) {
  const starts = [];
  let line = 0;
  for (const [name, text] of sources) {
    starts.push({ name, line });
    line += text.split("\n").length;
  }
  const diagnostics = await compiler.checkCode(sources.map(([, text]) => text).join("\n"));
  return diagnostics.map((d) => {
    const start = d.range.start;
    const file = starts.filter((s) => s.line <= start.line).at(-1);
    return {
      file: path.join(projectDir, file.name),
      line: start.line - file.line + 1,
      column: start.character + 1,
      severity: d.severity,
      code: d.code ?? "",
      message: d.message,
    };
  });
}

/** The callables and types the sources declare, by full name: their kind and whether they are internal. */
function declarations(sources) {
  const found = new Map();
  for (const [, text] of sources) {
    const namespace = text.match(/^\s*namespace\s+([\w.]+)/m)?.[1];
    for (const [, internal, kind, name] of text.matchAll(/^\s*(internal\s+)?(operation|function|struct|newtype)\s+(\w+)/gm)) {
      found.set(`${namespace}.${name}`, { kind, internal: internal !== undefined });
    }
  }
  return found;
}

/**
 * An error for each name entry-points.json lists that the library does not declare as a non-internal
 * callable ("operations") or type ("types"): the host names them in strings, so a rename would
 * otherwise fail only when a call runs.
 */
function checkEntryPoints(library) {
  const text = fs.readFileSync(entryPointsFile, "utf8");
  const listed = JSON.parse(text);
  const declared = declarations(library);
  const kinds = { operations: ["operation", "function"], types: ["struct", "newtype"] };
  const errors = [];
  for (const [group, allowed] of Object.entries(kinds)) {
    for (const name of listed[group] ?? []) {
      const item = declared.get(name);
      if (item && allowed.includes(item.kind) && !item.internal) continue;
      const problem = !item ? `no ${allowed.join(" or ")} of that name is declared under src/`
        : item.internal ? `src/ declares it internal`
        : `src/ declares it with "${item.kind}" and the "${group}" list takes ${allowed.join(" or ")}`;
      const lines = text.slice(0, text.indexOf(`"${name}"`)).split("\n");
      errors.push({
        file: entryPointsFile, line: lines.length, column: lines.at(-1).length + 1, severity: "error", code: "entry-points",
        message: `the host names ${name}, but ${problem}`,
      });
    }
  }
  return errors;
}

function formatDiagnostic(d) {
  const severity = d.severity === "error" ? "error" : "warning";
  return `${d.file}(${d.line},${d.column}): ${severity} QS: ${d.message} [${d.code}]`;
}

/** Turns the error value of a failed shot into the bridge's error object. */
function qsharpError(value) {
  if (typeof value === "string") return { kind: "qsharp", message: value };
  const first = value?.errors?.[0];
  const range = first?.diagnostic?.range?.start;
  return {
    kind: "qsharp",
    code: value?.code,
    message: first?.diagnostic?.message ?? value?.message ?? String(value),
    location: first && range ? `${first.document}:${range.line + 1}:${range.character + 1}` : undefined,
    stack: first?.stack ?? undefined,
  };
}

/** The bridge's error object for an exception the QDK threw (diagnostics with locations, or a message). */
function thrownError(e) {
  if (Array.isArray(e?.diagnostics) && e.diagnostics.length > 0) return qsharpError({ errors: e.diagnostics, message: e.message });
  return qsharpError(e?.message ?? String(e));
}

/** Operations a circuit may hold before the bridge refuses it (each costs memory in the QDK's JS object). */
const defaultMaxOperations = 2_000_000;

/** The namespace of the entry point the bridge adds for getCircuit, which takes no expression. */
const circuitEntryNamespace = "QuantumRayTracingCircuitEntry";

class RequestError extends Error {}

function requireString(request, field) {
  if (typeof request[field] !== "string" || request[field].length === 0) {
    throw new RequestError(`request field "${field}" must be a non-empty string`);
  }
  return request[field];
}

/** The run's noise ({pauli, qubitLoss}), or null when the request asks for none (the ideal path). */
function requestNoise(request) {
  if (request.noise === undefined && request.qubitLoss === undefined) return null;
  const pauli = request.noise ?? [0, 0, 0];
  const loss = request.qubitLoss ?? 0;
  const probability = (p) => typeof p === "number" && Number.isFinite(p) && p >= 0 && p <= 1;
  if (!Array.isArray(pauli) || pauli.length !== 3 || !pauli.every(probability) || pauli[0] + pauli[1] + pauli[2] > 1) {
    throw new RequestError(`request field "noise" must be [px, py, pz], probabilities summing to at most 1`);
  }
  if (!probability(loss) || loss >= 1) throw new RequestError(`request field "qubitLoss" must be a probability below 1`);
  return { pauli, qubitLoss: loss };
}

async function answer(compiler, program, versions, request) {
  switch (request.method) {
    case "version":
      return versions;
    case "run": {
      const expr = requireString(request, "expr");
      const shots = request.shots ?? 1;
      if (!Number.isInteger(shots) || shots < 1) throw new RequestError(`request field "shots" must be a positive integer`);
      const noise = requestNoise(request);
      const events = new QscEventTarget(true);
      try {
        if (noise) await compiler.runWithNoise(program, expr, shots, noise.pauli, noise.qubitLoss, events);
        else await compiler.run(program, expr, shots, events);
      } catch {
        // The failure is also recorded as a shot result, with its location; reported below.
      }
      const results = events.getResults();
      const failed = results.find((r) => !r.success);
      if (failed) return { error: qsharpError(failed.result) };
      if (results.length !== shots) return { error: { kind: "qsharp", message: `expected ${shots} shot results, got ${results.length}` } };
      return results.map((r) => r.result);
    }
    case "estimate": {
      const expr = requireString(request, "expr");
      const params = request.params ?? [{}];
      if (!Array.isArray(params)) throw new RequestError(`request field "params" must be an array of estimator parameter objects`);
      try {
        return JSON.parse(await compiler.getEstimates(program, expr, JSON.stringify(params)));
      } catch (e) {
        return { error: thrownError(e) };
      }
    }
    case "circuit": {
      // getCircuit runs the program's @EntryPoint, so the expression becomes the body of one. Only
      // "simulate" synthesises programs that branch on measurements (the standard library's
      // measurement-based uncomputation does), so the circuit is the trace of one simulated run.
      const expr = requireString(request, "expr");
      const limit = request.maxOperations ?? defaultMaxOperations;
      if (!Number.isInteger(limit) || limit < 1) throw new RequestError(`request field "maxOperations" must be a positive integer`);
      const entry = `namespace ${circuitEntryNamespace} { @EntryPoint() operation Main() : Unit { let _ = ${expr}; } }`;
      const withEntry = { ...program, sources: [...program.sources, ["circuit-entry.qs", entry]] };
      let group;
      try {
        // One operation past the limit shows truncation: getCircuit stops there without saying so.
        group = await compiler.getCircuit(withEntry, { generationMethod: "simulate", maxOperations: limit + 1, sourceLocations: false, groupByScope: false });
      } catch (e) {
        return { error: thrownError(e) };
      }
      const marked = request.marked ?? null;
      if (marked !== null && !(Array.isArray(marked) && marked.every(Number.isInteger))) throw new RequestError(`request field "marked" must be an array of integers`);
      const fraction = request.harmFraction ?? 1;
      if (typeof fraction !== "number" || !(fraction > 0 && fraction <= 1)) throw new RequestError(`request field "harmFraction" must be a number in (0, 1]`);
      const seed = request.harmSeed ?? 1;
      if (!Number.isInteger(seed) || seed < 0 || seed > 0xffffffff) throw new RequestError(`request field "harmSeed" must be an integer from 0 to 2^32 - 1`);
      const summary = summariseCircuit(group, request.exposure === true, request.harm === true ? marked ?? [] : null, { fraction, seed });
      if (summary.operations > limit) {
        return { error: { kind: "qsharp", message: `the circuit has more than ${limit} operations (maxOperations); ask for a smaller circuit or raise the limit` } };
      }
      return summary;
    }
    case "export": {
      const apply = requireString(request, "apply");
      const qubits = request.qubits;
      if (!Number.isInteger(qubits) || qubits < 1 || qubits > 30) throw new RequestError(`request field "qubits" must be an integer from 1 to 30`);
      const measured = request.measured ?? qubits;
      if (!Number.isInteger(measured) || measured < 1 || measured > qubits) throw new RequestError(`request field "measured" must be an integer from 1 to "qubits"`);
      const profile = request.profile ?? "adaptive_ri";
      if (!["base", "adaptive_ri"].includes(profile)) throw new RequestError(`request field "profile" must be "base" or "adaptive_ri"`);
      const withEntry = { ...program, sources: [...program.sources, ["export-entry.qs", exportEntrySource(apply, qubits, measured)]] };
      const events = new QscEventTarget(true);
      try {
        await compiler.run(withEntry, `${exportEntryNamespace}.DumpState()`, 1, events);
      } catch {
        // Reported from the shot result below.
      }
      const shot = events.getResults()[0];
      if (!shot?.success) return { error: qsharpError(shot?.result ?? "the state dump did not run") };
      const dump = shot.events.find((e) => e.type === "DumpMachine");
      if (!dump) return { error: { kind: "qsharp", message: "the state dump produced no DumpMachine event" } };
      let qir;
      try {
        qir = await compiler.getQir({ ...withEntry, profile });
      } catch (e) {
        return { error: thrownError(e) };
      }
      return { qir, probabilities: registerDistribution(dump, qubits, measured) };
    }
    default:
      throw new RequestError(`unknown method ${JSON.stringify(request.method)}; expected version, run, estimate, circuit or export`);
  }
}

async function serve(compiler, sources) {
  const program = { sources, languageFeatures: [], profile: "unrestricted" };
  const versions = {
    qsharp: JSON.parse(fs.readFileSync(path.join(packageDir, "package.json"), "utf8")).version,
    node: process.version,
  };
  const write = (reply) => process.stdout.write(JSON.stringify(reply) + "\n");
  const diagnostics = (await checkSources(compiler, sources)).filter((d) => d.severity === "error");
  if (diagnostics.length > 0) {
    write({ ready: false, error: { kind: "compile", message: diagnostics.map(formatDiagnostic).join("\n") } });
    process.exit(1);
  }
  write({ ready: true, ...versions });

  const lines = readline.createInterface({ input: process.stdin, crlfDelay: Infinity });
  for await (const line of lines) {
    if (line.trim() === "") continue;
    let request;
    try {
      request = JSON.parse(line);
    } catch (e) {
      write({ id: null, ok: false, error: { kind: "request", message: `request is not JSON: ${e.message}` } });
      continue;
    }
    const id = request?.id ?? null;
    try {
      const result = await answer(compiler, program, versions, request ?? {});
      write(result?.error ? { id, ok: false, error: result.error } : { id, ok: true, result });
    } catch (e) {
      const kind = e instanceof RequestError ? "request" : "bridge";
      write({ id, ok: false, error: { kind, message: e?.message ?? String(e), stack: e?.stack } });
    }
  }
}

const compiler = await loadCompiler();
const library = readSources(sourceDir);
const tests = readSources(testDir);
if (process.argv.includes("--check")) {
  const isError = (d) => d.severity === "error";
  const diagnostics = await checkSources(compiler, [...library, ...tests]);
  // The host's bridges load src/ alone, so it must compile without the tests.
  if (!diagnostics.some(isError)) diagnostics.push(...(await checkSources(compiler, library)).filter(isError));
  diagnostics.push(...checkEntryPoints(library));
  for (const d of diagnostics) console.log(formatDiagnostic(d));
  const errors = diagnostics.filter(isError).length;
  console.log(`Q#: ${library.length} library files, ${tests.length} test files, ${errors} errors, ${diagnostics.length - errors} warnings`);
  process.exit(errors > 0 ? 1 : 0);
} else {
  await serve(compiler, process.env.QRT_QSHARP_TESTS === "1" ? [...library, ...tests] : library);
}
