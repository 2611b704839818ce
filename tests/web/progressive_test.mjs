// A progressive .glb in a real browser (Debian's Chromium, headless, driven by puppeteer-core),
// served by vrsimplify's own server with its bandwidth throttled:
//   - the base is drawn first, from a small share of the file, and the mesh then refines
//     while the bytes arrive (the records applied grow at many byte counts before the last);
//   - every record is applied in the end: the faces and vertices the file announces;
//   - the longest frame while refining and the longest refining step (printed: figures);
//   - the file's first N records as the page streamed them look like the same N records applied
//     by three.js's GLTFLoader with the VRS_mesh_progressive plugin (screenshots compared), for
//     N = the records whole in 1 %, 5 %, 20 % and 100 % of the file's bytes (the pictures kept);
//   - the browser's decoder speed, in records per second.
// Writes the screenshots and a JSON of the figures to OUT_DIR.
//   node tests/web/progressive_test.mjs SERVE_PY FILE.glb OUT_DIR [--throttle B/s]
//        [--max-first F] [--stream-only | --decoder-only]
// --decoder-only: the base drawn and the decoder's speed, not the whole stream (huge meshes,
// whose every frame SwiftShader draws in seconds).
import { mkdir, readFile, writeFile } from "node:fs/promises";
import path from "node:path";

import { checkAgainstLoader, launchBrowser, openPage as open, progressiveFile, startServer }
  from "./harness.mjs";
import { checks } from "./checks.mjs";

const [servePy, glb, outDir, ...rest] = process.argv.slice(2);
const option = (name, fallback) => {
  const i = rest.indexOf(name);
  return i >= 0 ? Number(rest[i + 1]) : fallback;
};
const throttle = option("--throttle", 500_000);
const maxFirst = option("--max-first", 0.02);
const decoderOnly = rest.includes("--decoder-only");
const streamOnly = decoderOnly || rest.includes("--stream-only"); // no prefix renders
const { check, failed } = checks({ everyOne: true });

const file = new Uint8Array(await readFile(glb));
const { layout, recordsWithin } = progressiveFile(file);

await mkdir(outDir, { recursive: true });
const { server, base } = await startServer(servePy, glb, throttle);
const browser = await launchBrowser(480, 360);
const openPage = (query) => open(browser, base, glb, query, 480, 360);
const name = encodeURIComponent(path.basename(glb));

const figures = { file: path.basename(glb), throttle, bytes: file.length,
                  insertions: layout.insertions, prefixes: [] };
try {
  const streamed = await openPage(decoderOnly ? "&stop=0" : "");
  check(streamed.errors.length === 0, `no page error ${streamed.errors.join("; ")}`);
  const p = streamed.state.progressive;
  const total = streamed.state.total;
  check(total === file.length, `the page read ${total} bytes of ${file.length}`);
  if (decoderOnly) Object.assign(figures, { baseBytes: p.baseBytes, baseMs: p.baseMs });
  if (!decoderOnly) {
    check(p.baseBytes <= maxFirst * total,
          `base drawn after ${p.baseBytes} of ${total} bytes (${((100 * p.baseBytes) / total).toFixed(2)} %, ` +
          `at most ${100 * maxFirst} %)`);
    check(p.applied === layout.insertions && p.faces === layout.faceCount &&
          p.vertices === layout.vertexCount,
          `every record applied: ${p.applied} records, ${p.faces} faces, ${p.vertices} vertices`);
    const beforeLast = p.samples.filter(([, bytes]) => bytes < total);
    const distinctBytes = new Set(beforeLast.map(([, bytes]) => bytes)).size;
    check(distinctBytes >= 5 && beforeLast.every((s, i) => i === 0 || s[2] > beforeLast[i - 1][2]),
          `refined at ${distinctBytes} byte counts before the last byte, more records each time`);
    // Figures, not checks: a test's timings judge the machine it runs on (bench/PROGRESSIVE.md).
    console.log(`info longest frame while refining ${p.longestFrameMs.toFixed(1)} ms, ` +
                `longest refining step ${p.longestRefineMs.toFixed(1)} ms`);
    Object.assign(figures, { baseBytes: p.baseBytes, baseMs: p.baseMs, doneMs: p.doneMs,
                             longestFrameMs: p.longestFrameMs, longestRefineMs: p.longestRefineMs,
                             samples: p.samples.length });
  }
  // The decoder's speed in this browser, the whole file's records and no drawing: in the
  // viewer's page (SwiftShader draws its frames on the same two cores) and on a page of its
  // own (as beside a GPU, which draws without the CPU).
  const decoderSpeed = (page) => page.evaluate(async (url) => {
    const m = await import("./progressive.js");
    const bytes = new Uint8Array(await (await fetch(url)).arrayBuffer());
    const h = m.readHeader(bytes);
    const l = m.describeProgressive(h.json);
    let best = 0;
    for (let run = 0; run < 3; run++) {
      const bin = bytes.subarray(h.binStart);
      const d = new m.ProgressiveDecoder(l, bin);
      d.push(bin.subarray(l.recordStart, l.recordStart + l.recordBytes));
      const t = performance.now();
      d.apply();
      best = Math.max(best, d.applied / ((performance.now() - t) / 1000));
    }
    return best;
  }, `/${name}`);
  figures.recordsPerSecondInViewer = await decoderSpeed(streamed.page);
  await streamed.page.close();
  const alone = await browser.newPage();
  await alone.goto(`${base}progressive.js`); // the server's origin, nothing drawn
  figures.recordsPerSecond = await decoderSpeed(alone);
  await alone.close();
  console.log(`info decoder: ${(figures.recordsPerSecond / 1e6).toFixed(2)} M records/s on a page ` +
              `of its own, ${(figures.recordsPerSecondInViewer / 1e6).toFixed(2)} M in the viewer's`);

  // Prefixes: streamed and stopped against GLTFLoader with the plugin, the same records.
  for (const share of streamOnly ? [] : [0.01, 0.05, 0.2, 1]) {
    const records = recordsWithin(Math.round(share * file.length));
    if (records < 0) {
      console.log(`info ${100 * share} % of the bytes hold no whole base`);
      continue;
    }
    const a = await openPage(`&stop=${records}`);
    const b = await openPage(`&reference=${records}`);
    check(a.state.progressive.faces === b.state.progressive.faces,
          `${100 * share} % of the bytes, ${records} records: ${a.state.progressive.faces} faces ` +
          `streamed, ${b.state.progressive.faces} through GLTFLoader`);
    const faces = a.state.progressive.faces;
    const pixelsDiffer = await checkAgainstLoader(a, b, { label: `${100 * share} %`, check, outDir,
                                                          stem: `bytes-${100 * share}pct` });
    figures.prefixes.push({ share, records, faces, pixelsDiffer });
  }
} finally {
  await browser.close();
  server.kill();
  await writeFile(path.join(outDir, "figures.json"), JSON.stringify(figures, null, 1));
}
console.log(failed() ? `${failed()} check(s) failed` : "all checks passed");
process.exit(failed() ? 1 : 0);
