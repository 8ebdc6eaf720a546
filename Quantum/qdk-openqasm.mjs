// Compiles an OpenQASM file (2.0 or 3.0) with the QDK's OpenQASM import to QIR (adaptive profile) and,
// with --shots S, runs it S times on the QDK's simulator:
//
//   node qdk-openqasm.mjs FILE [--shots S]   ->   {"qirInstructions":434,"shots":{"[One, One, Zero]":100}}
//
// The check that a file `qrt export` wrote reads back as a program another toolchain accepts. With --serve it
// checks many files in one process (check-serve.mjs), loading the QDK once.

import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";
import { getCompiler, loadWasmModule, QscEventTarget } from "qsharp-lang";
import { runCheck, UsageError } from "./check-serve.mjs";

const packageDir = path.join(path.dirname(fileURLToPath(import.meta.url)), "node_modules", "qsharp-lang");
let compiler = null;

/** The reply for one file. */
async function check(args) {
  const [file] = args;
  const shotsAt = args.indexOf("--shots");
  const shots = shotsAt > 0 ? Number(args[shotsAt + 1]) : 0;
  if (!file || !Number.isInteger(shots) || shots < 0) throw new UsageError();
  if (compiler === null) {
    const wasm = fs.readFileSync(path.join(packageDir, "lib", "web", "qsc_wasm_bg.wasm"));
    await loadWasmModule(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
    compiler = await getCompiler();
  }
  const program = { sources: [[path.basename(file), fs.readFileSync(file, "utf8")]], languageFeatures: [], profile: "adaptive_ri", projectType: "openqasm" };
  let qir;
  try {
    qir = await compiler.getQir(program);
  } catch (e) {
    const first = e?.diagnostics?.[0]?.diagnostic;
    throw new Error(`the QDK cannot compile ${file}: ${first ? `line ${first.range.start.line + 1}: ${first.message}` : e?.message ?? e}`);
  }
  const reply = { qirInstructions: (qir.match(/call \S+ @__quantum__qis__/g) ?? []).length };
  if (shots > 0) {
    const events = new QscEventTarget(true);
    await compiler.run(program, "", shots, events);
    const histogram = {};
    for (const r of events.getResults()) {
      if (!r.success) throw new Error(`a shot failed: ${JSON.stringify(r.result)}`);
      const key = typeof r.result === "string" ? r.result : JSON.stringify(r.result);
      histogram[key] = (histogram[key] ?? 0) + 1;
    }
    reply.shots = histogram;
  }
  return reply;
}

await runCheck("node qdk-openqasm.mjs FILE [--shots S] | --serve", check);
