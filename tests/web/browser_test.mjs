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
import { spawn } from "node:child_process";
import { mkdir, writeFile } from "node:fs/promises";
import { createRequire } from "node:module";
import path from "node:path";

const require = createRequire(new URL("../../web/package.json", import.meta.url));
const puppeteer = require("puppeteer-core");

const [servePy, glb, outDir, ...rest] = process.argv.slice(2);
const option = (name, fallback) => {
  const i = rest.indexOf(name);
  return i >= 0 ? Number(rest[i + 1]) : fallback;
};
const throttle = option("--throttle", 2_000_000);
const maxFirst = option("--max-first", 0.02); // share of the file the coarsest level may need
const streamOnly = rest.includes("--stream-only"); // the streaming checks, no per-level renders
const python = process.env.VRS_PYTHON || "python3";
const chromium = process.env.CHROMIUM || "/usr/bin/chromium";
let failures = 0;
const check = (ok, what) => {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures++;
};

await mkdir(outDir, { recursive: true });
const server = spawn(python, [servePy, glb, "--port", "0", "--throttle", String(throttle)], {
  stdio: ["ignore", "pipe", "inherit"],
});
const base = await new Promise((resolve, reject) => {
  let text = "";
  server.stdout.on("data", (d) => {
    text += d;
    const m = text.match(/at (http:\/\/[^/]+\/)/);
    if (m) resolve(m[1]);
  });
  server.on("exit", (code) => reject(new Error(`server exited (${code})`)));
  setTimeout(() => reject(new Error("server did not start")), 20000);
});
const name = encodeURIComponent(path.basename(glb));

const browser = await puppeteer.launch({
  executablePath: chromium,
  headless: true,
  args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
         "--ignore-gpu-blocklist", "--window-size=480,360"],
});

async function openPage(query) {
  const page = await browser.newPage();
  await page.setViewport({ width: 480, height: 360 });
  const errors = [];
  page.on("pageerror", (e) => errors.push(String(e)));
  await page.goto(`${base}index.html?url=/${name}${query}`);
  await page.waitForFunction("window.viewer && (window.viewer.done || window.viewer.error)",
                             { timeout: 300000, polling: 50 });
  await page.waitForFunction("window.viewer.textureReady", { timeout: 60000 });
  await new Promise((r) => setTimeout(r, 300)); // a few frames with everything in place
  const state = await page.evaluate(() => window.viewer);
  if (state.error) errors.push(state.error);
  if (state.textureError) errors.push(`texture not loaded: ${state.textureError}`);
  return { page, state, errors };
}

async function pixels(page) {
  return page.evaluate(() => {
    const c = document.querySelector("#view canvas");
    const t = document.createElement("canvas");
    t.width = c.width;
    t.height = c.height;
    const g = t.getContext("2d");
    g.drawImage(c, 0, 0);
    return Array.from(g.getImageData(0, 0, t.width, t.height).data);
  });
}

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
    check(a.errors.length === 0 && b.errors.length === 0,
          `level ${k}: no page error ${[...a.errors, ...b.errors].join("; ")}`);
    const faces = b.state.levels[0]?.faces;
    check(a.state.levels.at(-1)?.faces === faces,
          `level ${k}: ${a.state.levels.at(-1)?.faces} faces streamed, ${faces} read by GLTFLoader`);
    const pa = await pixels(a.page);
    const pb = await pixels(b.page);
    let differ = 0, drawn = 0;
    for (let i = 0; i < pa.length; i += 4) {
      const d = Math.max(Math.abs(pa[i] - pb[i]), Math.abs(pa[i + 1] - pb[i + 1]),
                         Math.abs(pa[i + 2] - pb[i + 2]));
      if (d > 24) differ++;
      if (pb[i] !== 0x20 || pb[i + 1] !== 0x24 || pb[i + 2] !== 0x2a) drawn++;
    }
    const share = differ / (pa.length / 4);
    check(drawn > 0.02 * (pa.length / 4), `level ${k}: the model covers ${drawn} pixels`);
    check(share < 0.01, `level ${k}: ${(100 * share).toFixed(3)} % of pixels differ from GLTFLoader's`);
    figures.levels.find((l) => l.index === k).pixelsDiffer = share;
    await a.page.screenshot({ path: path.join(outDir, `level-${k}-streamed.png`) });
    await b.page.screenshot({ path: path.join(outDir, `level-${k}-gltfloader.png`) });
    await a.page.close();
    await b.page.close();
  }
} finally {
  await browser.close();
  server.kill();
  await writeFile(path.join(outDir, "figures.json"), JSON.stringify(figures, null, 1));
}
console.log(failures ? `${failures} check(s) failed` : "all checks passed");
process.exit(failures ? 1 : 0);
