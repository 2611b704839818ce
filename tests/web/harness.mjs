// What the browser tests share: vrsimplify's own server on a free port, Debian's Chromium
// headless (SwiftShader) through puppeteer-core, the viewer page opened and waited for, its
// pixels read back and compared, and a progressive file's records within a byte prefix.
import { spawn } from "node:child_process";
import { createRequire } from "node:module";
import path from "node:path";

import { ProgressiveDecoder, describeProgressive, readHeader } from "../../web/progressive.js";

const require = createRequire(new URL("../../web/package.json", import.meta.url));
const puppeteer = require("puppeteer-core");

// `vrsimplify serve` (SERVE_PY run by $VRS_PYTHON) on `glb`: { server, base } once it listens.
export async function startServer(servePy, glb, throttle = 0) {
  const python = process.env.VRS_PYTHON || "python3";
  const args = [servePy, glb, "--port", "0"];
  if (throttle) args.push("--throttle", String(throttle));
  const server = spawn(python, args, { stdio: ["ignore", "pipe", "inherit"] });
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
  return { server, base };
}

export function launchBrowser(width, height) {
  return puppeteer.launch({
    executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
    headless: true,
    args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
           "--ignore-gpu-blocklist", `--window-size=${width},${height}`],
  });
}

// The viewer page on `glb` with `query`, once it is done (or failed) and its texture is in:
// { page, state (window.viewer), errors }.
export async function openPage(browser, base, glb, query, width, height) {
  const page = await browser.newPage();
  await page.setViewport({ width, height });
  const errors = [];
  page.on("pageerror", (e) => errors.push(String(e)));
  await page.goto(`${base}index.html?url=/${encodeURIComponent(path.basename(glb))}${query}`);
  await page.waitForFunction("window.viewer && (window.viewer.done || window.viewer.error)",
                             { timeout: 600000, polling: 50 });
  await page.waitForFunction("window.viewer.textureReady", { timeout: 60000 });
  await new Promise((r) => setTimeout(r, 300)); // a few frames with everything in place
  const state = await page.evaluate(() => window.viewer);
  if (state.error) errors.push(state.error);
  if (state.textureError) errors.push(`texture not loaded: ${state.textureError}`);
  return { page, state, errors };
}

// The canvas's RGBA bytes.
export async function pixels(page) {
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

// Two pictures of the page's size: the share of pixels that differ by more than 24 in a
// channel, and how many pixels of `b` are not the background (the model's cover).
export function compare(a, b) {
  let differ = 0, drawn = 0;
  for (let i = 0; i < a.length; i += 4) {
    const d = Math.max(Math.abs(a[i] - b[i]), Math.abs(a[i + 1] - b[i + 1]), Math.abs(a[i + 2] - b[i + 2]));
    if (d > 24) differ++;
    if (b[i] !== 0x20 || b[i + 1] !== 0x24 || b[i + 2] !== 0x2a) drawn++;
  }
  return { share: differ / (a.length / 4), drawn, count: a.length / 4 };
}

// A progressive file's layout, and the records whole in its first `bytes` bytes (-1: not even
// the base).
export function progressiveFile(file) {
  const header = readHeader(file);
  const layout = describeProgressive(header.json);
  const recordsWithin = (bytes) => {
    const bin = file.subarray(header.binStart, Math.max(header.binStart, bytes));
    if (bin.length < layout.recordStart) return -1;
    const d = new ProgressiveDecoder(layout, file.subarray(header.binStart));
    d.push(bin.subarray(layout.recordStart));
    d.apply();
    return d.applied;
  };
  return { header, layout, recordsWithin, baseBytes: header.binStart + layout.recordStart };
}

// The same picture twice — `a` as the page streamed it, `b` as GLTFLoader read the whole file:
// checks that neither page failed, that the model covers the view and that under 1 % of the
// pixels differ; writes both screenshots (OUT_DIR/STEM-streamed.png, -gltfloader.png), closes
// the pages and returns the share of pixels that differ.
export async function checkAgainstLoader(a, b, { label, check, outDir, stem }) {
  check(a.errors.length === 0 && b.errors.length === 0,
        `${label}: no page error ${[...a.errors, ...b.errors].join("; ")}`);
  const { share, drawn, count } = compare(await pixels(a.page), await pixels(b.page));
  check(drawn > 0.02 * count, `${label}: the model covers ${drawn} pixels`);
  check(share < 0.01, `${label}: ${(100 * share).toFixed(3)} % of pixels differ from GLTFLoader's`);
  await a.page.screenshot({ path: path.join(outDir, `${stem}-streamed.png`) });
  await b.page.screenshot({ path: path.join(outDir, `${stem}-gltfloader.png`) });
  await a.page.close();
  await b.page.close();
  return share;
}
