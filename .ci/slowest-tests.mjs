// Prints the N slowest tests of a trx file (the test logger's XML) with their durations, and the sum over all tests.
//   node .ci/slowest-tests.mjs results.trx [N]
import fs from "node:fs";

const [file, count = "15"] = process.argv.slice(2);
const text = fs.readFileSync(file, "utf8");
const seconds = (d) => d.split(":").reduce((total, part) => total * 60 + Number(part), 0);
const attribute = (tag, name) => tag.match(new RegExp(`\\s${name}="([^"]*)"`))?.[1];

const results = [...text.matchAll(/<UnitTestResult\s[^>]*>/g)].map(([tag]) => ({
  name: attribute(tag, "testName").replaceAll("&quot;", '"').replaceAll("&amp;", "&").replaceAll("&lt;", "<").replaceAll("&gt;", ">"),
  seconds: seconds(attribute(tag, "duration") ?? "0:0:0"),
  outcome: attribute(tag, "outcome"),
}));
results.sort((a, b) => b.seconds - a.seconds);
const total = results.reduce((sum, r) => sum + r.seconds, 0);
console.log(`${results.length} tests, their durations summing to ${total.toFixed(0)} s (tests run two at a time on two cores)`);
console.log(`the ${Math.min(Number(count), results.length)} slowest:`);
for (const r of results.slice(0, Number(count)))
  console.log(`${r.seconds.toFixed(1).padStart(7)} s  ${r.outcome === "Passed" ? "" : `[${r.outcome}] `}${r.name.replace(/^QuantumRayTracing\.Tests\./, "")}`);
