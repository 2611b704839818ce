// Khronos' glTF-Validator over every .glb given: prints its counts, fails on any error or
// warning (infos and hints are listed, not failures). External images are read beside the file.
//   node tests/web/validate_glb.mjs FILE.glb...
import { createRequire } from "node:module";
import { readFile } from "node:fs/promises";
import path from "node:path";

const require = createRequire(new URL("../../web/package.json", import.meta.url));
const validator = require("gltf-validator");

let failed = 0;
for (const file of process.argv.slice(2)) {
  const bytes = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 100,
    externalResourceFunction: (uri) =>
      readFile(path.join(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
  });
  const { numErrors, numWarnings, numInfos, numHints } = report.issues;
  console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ${numHints} hints`);
  for (const m of report.issues.messages)
    console.log(`  [${["error", "warning", "info", "hint"][m.severity]}] ${m.code}: ${m.message} (${m.pointer ?? ""})`);
  if (numErrors || numWarnings) failed++;
}
process.exit(failed ? 1 : 0);
