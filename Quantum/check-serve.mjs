// How each check script (check-openqasm.mjs, check-openqasm-jsqubits.mjs, qdk-openqasm.mjs) runs: once, on its
// command-line arguments, printing its one JSON reply; or, with --serve, for many files in one process, so the
// simulator or the QDK loads once (the C# tests check dozens of files): each line on stdin is a JSON array of the
// arguments, each reply one line on stdout, {"ok":true,"result":<the reply>} or {"ok":false,"error":"<message>"}.

import readline from "node:readline";

/** A wrong command line: the script prints its usage. */
export class UsageError extends Error {}

/** Runs `check(args)` (async, returning the reply object) as the command line asks. */
export async function runCheck(usage, check) {
  const args = process.argv.slice(2);
  if (args[0] !== "--serve") {
    try {
      console.log(JSON.stringify(await check(args)));
    } catch (e) {
      console.error(e instanceof UsageError ? `usage: ${usage}` : e?.message ?? String(e));
      process.exit(e instanceof UsageError ? 2 : 1);
    }
    return;
  }
  for await (const line of readline.createInterface({ input: process.stdin })) {
    let reply;
    try {
      reply = { ok: true, result: await check(JSON.parse(line)) };
    } catch (e) {
      reply = { ok: false, error: e instanceof UsageError ? `usage: ${usage}` : e?.message ?? String(e) };
    }
    process.stdout.write(`${JSON.stringify(reply)}\n`);
  }
}
