// Pictures of a progressive .glb after given shares of its bytes: for each share, the records
// whole in that prefix applied by three.js's GLTFLoader with the VRS_mesh_progressive plugin
// (the viewer page's &reference=N), in headless Chromium; the share "base" is the base alone.
// Writes OUT_DIR/bytes-<share>.png and prints one line a picture: share, records, faces, and
// the share of the bytes they need.
//   node tests/web/progressive_pictures.mjs SERVE_PY FILE.glb OUT_DIR SHARE...
import { mkdir, readFile } from "node:fs/promises";
import path from "node:path";

import { launchBrowser, progressiveFile, startServer } from "./harness.mjs";

const [servePy, glb, outDir, ...shares] = process.argv.slice(2);
const file = new Uint8Array(await readFile(glb));
const { recordsWithin, baseBytes } = progressiveFile(file);
await mkdir(outDir, { recursive: true });
const { server, base } = await startServer(servePy, glb);
const browser = await launchBrowser(360, 360);
let failed = 0;
try {
  for (const share of shares) {
    const records = share === "base" ? 0 : recordsWithin(Math.round(Number(share) * file.length));
    if (records < 0) {
      console.log(`${share}: the base is not whole yet`);
      failed++;
      continue;
    }
    const page = await browser.newPage();
    await page.setViewport({ width: 360, height: 360 });
    await page.goto(`${base}index.html?url=/${encodeURIComponent(path.basename(glb))}&reference=${records}`);
    await page.waitForFunction("window.viewer && (window.viewer.done || window.viewer.error)",
                               { timeout: 600000, polling: 100 });
    await page.evaluate(() => { document.getElementById("panel").style.display = "none"; });
    await new Promise((r) => setTimeout(r, 500));
    const state = await page.evaluate(() => window.viewer);
    if (state.error) {
      console.log(`${share}: ${state.error}`);
      failed++;
    }
    await page.screenshot({ path: path.join(outDir, `bytes-${share}.png`) });
    const needed = share === "base" ? baseBytes : Number(share) * file.length;
    console.log(`${share} ${records} ${state.progressive?.faces} ${(needed / file.length).toFixed(4)}`);
    await page.close();
  }
} finally {
  await browser.close();
  server.kill();
}
process.exit(failed ? 1 : 0);
