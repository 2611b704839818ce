// The viewer page in a real browser (Debian's Chromium, headless, driven by puppeteer-core),
// served by vrsimplify's own server with its bandwidth throttled:
//   - the coarsest level is drawn first, from a small share of the file, before the rest has
//     arrived; every finer level follows, in order;
//   - each level as the page streamed it looks like the same level read by three.js's own
//     GLTFLoader from the whole file (screenshots compared pixel by pixel);
//   - the page's numbers (faces per level) are the file's.
// Writes the screenshots and a JSON of the figures to OUT_DIR.
//   node tests/web/browser_test.mjs SERVE_PY FILE.glb OUT_DIR [--throttle B/s] [--max-first F]
//                                   [--stream-only]
import { mkdir, writeFile } from "node:fs/promises";
import path from "node:path";

import { checkAgainstLoader, launchBrowser, openPage as open, startServer } from "./harness.mjs";
import { checks } from "./checks.mjs";

const [servePy, glb, outDir, ...rest] = process.argv.slice(2);
const option = (name, fallback) => {
  const i = rest.indexOf(name);
  return i >= 0 ? Number(rest[i + 1]) : fallback;
};
const throttle = option("--throttle", 2_000_000);
const maxFirst = option("--max-first", 0.02); // share of the file the coarsest level may need
const streamOnly = rest.includes("--stream-only"); // the streaming checks, no per-level renders
const { check, failed } = checks({ everyOne: true });

await mkdir(outDir, { recursive: true });
const { server, base } = await startServer(servePy, glb, throttle);
const browser = await launchBrowser(480, 360);
const openPage = (query) => open(browser, base, glb, query, 480, 360);

const figures = { file: path.basename(glb), throttle, levels: [] };
try {
  // Streamed, throttled: the order and the bytes each level needed.
  const streamed = await openPage("");
  check(streamed.errors.length === 0, `no page error ${streamed.errors.join("; ")}`);
  const s = streamed.state;
  const n = s.levels.length;
  check(n >= 1 && s.levels.every((l, i) => i === 0 || l.index === s.levels[i - 1].index - 1),
        `levels drawn coarsest first, each after the coarser one (${s.levels.map((l) => l.index)})`);
  const first = s.levels[0];
  check(first.bytes <= maxFirst * s.total,
        `coarsest level drawn after ${first.bytes} of ${s.total} bytes ` +
        `(${((100 * first.bytes) / s.total).toFixed(2)} %, at most ${100 * maxFirst} %)`);
  check(n === 1 || first.ms < s.levels[n - 1].ms,
        `coarsest drawn at ${first.ms.toFixed(0)} ms, finest at ${s.levels[n - 1].ms.toFixed(0)} ms`);
  check(s.bytes <= s.total, `received ${s.bytes} of ${s.total} bytes in all`);
  figures.total = s.total;
  figures.levels = s.levels;
  await streamed.page.screenshot({ path: path.join(outDir, "streamed-finest.png") });
  await streamed.page.close();

  // Each level: streamed (stopped there) against GLTFLoader's reading of the whole file.
  for (const level of streamOnly ? [] : s.levels) {
    const k = level.index;
    const a = await openPage(`&stop=${k}`);
    const b = await openPage(`&reference=${k}`);
    const faces = b.state.levels[0]?.faces;
    check(a.state.levels.at(-1)?.faces === faces,
          `level ${k}: ${a.state.levels.at(-1)?.faces} faces streamed, ${faces} read by GLTFLoader`);
    figures.levels.find((l) => l.index === k).pixelsDiffer =
      await checkAgainstLoader(a, b, { label: `level ${k}`, check, outDir, stem: `level-${k}` });
  }
} finally {
  await browser.close();
  server.kill();
  await writeFile(path.join(outDir, "figures.json"), JSON.stringify(figures, null, 1));
}
console.log(failed() ? `${failed()} check(s) failed` : "all checks passed");
process.exit(failed() ? 1 : 0);
