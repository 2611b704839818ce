// A progressive .glb decoded by the browser's decoder (web/progressive.js, in Node) against the
// full mesh written alone (--lods 1):
//   - once every record is applied, the same faces, each corner the same vertex record bit for
//     bit (positions, normals, colors, texture coordinates), as many vertices as announced;
//   - fed in pieces of awkward sizes and applied between them (a record cut anywhere waits for
//     its bytes), the decoder ends with the same vertex and index bytes as fed the whole file;
//   - a stream of another version is refused.
//   node tests/web/progressive_decoded.mjs PROGRESSIVE.glb FULL.glb
import { readFileSync } from "node:fs";

import { ProgressiveDecoder, describeProgressive, readHeader } from "../../web/progressive.js";
import { checks } from "./checks.mjs";

const [progressivePath, fullPath] = process.argv.slice(2);
const { check, failed } = checks();

// Faces as sorted triples of vertex records (each rotated to start at its smallest record).
function asRecords(vertices, stride, indices, faceCount) {
  const record = (v) => Buffer.from(vertices.subarray(v * stride, (v + 1) * stride)).toString("hex");
  const out = [];
  for (let f = 0; f < faceCount; f++) {
    const r = [0, 1, 2].map((c) => record(indices[3 * f + c]));
    let k = 0;
    for (let c = 1; c < 3; c++) if (r[c] < r[k]) k = c;
    out.push([...r.slice(k), ...r.slice(0, k)].join(","));
  }
  return out.sort();
}

function fullMesh(path) {
  const file = new Uint8Array(readFileSync(path));
  const { json, binStart } = readHeader(file);
  const bin = file.subarray(binStart);
  const prim = json.meshes[json.nodes[json.scenes[json.scene ?? 0].nodes[0]].mesh].primitives[0];
  const pos = json.accessors[prim.attributes.POSITION];
  const view = json.bufferViews[pos.bufferView];
  const vertices = bin.subarray(view.byteOffset ?? 0, (view.byteOffset ?? 0) + pos.count * view.byteStride);
  const ia = json.accessors[prim.indices];
  const iview = json.bufferViews[ia.bufferView];
  const at = (iview.byteOffset ?? 0) + (ia.byteOffset ?? 0);
  const raw = bin.slice(at, at + ia.count * (ia.componentType === 5125 ? 4 : 2)).buffer;
  const indices = ia.componentType === 5125 ? new Uint32Array(raw) : new Uint16Array(raw);
  return asRecords(vertices, view.byteStride, indices, ia.count / 3);
}

const file = new Uint8Array(readFileSync(progressivePath));
const { json, binStart } = readHeader(file);
const layout = describeProgressive(json);
const bin = file.subarray(binStart);
const records = bin.subarray(layout.recordStart, layout.recordStart + layout.recordBytes);

const whole = new ProgressiveDecoder(layout, bin);
whole.push(records);
whole.apply();
check(whole.applied === layout.insertions, `applied ${whole.applied} of ${layout.insertions} records`);
check(whole.faceCount === layout.faceCount && whole.vertexCount === layout.vertexCount,
      `${whole.faceCount} faces, ${whole.vertexCount} vertices: the file announces ` +
      `${layout.faceCount} and ${layout.vertexCount}`);
const decoded = asRecords(whole.vertices, layout.stride, whole.indices, whole.faceCount);
const full = fullMesh(fullPath);
check(decoded.length === full.length && decoded.every((r, i) => r === full[i]),
      "the faces and vertex records of the full mesh");

// A stream of another coding (version 2: residuals as varints) is refused, not misread.
let refused = "";
try {
  new ProgressiveDecoder({ ...layout, version: 2 }, bin);
} catch (e) {
  refused = String(e);
}
check(/version 2/.test(refused), `a version 2 stream refused: ${refused || "it was read"}`);

const pieces = new ProgressiveDecoder(layout, bin);
let seed = 7;
for (let at = 0; at < records.length;) {
  seed = (seed * 1103515245 + 12345) % 2147483648;
  const n = 1 + (seed % 97);
  pieces.push(records.subarray(at, at + n));
  at += n;
  pieces.apply();
}
check(pieces.applied === layout.insertions, `in pieces: applied ${pieces.applied}`);
check(Buffer.compare(Buffer.from(pieces.vertices), Buffer.from(whole.vertices)) === 0 &&
      Buffer.compare(Buffer.from(pieces.indices.buffer), Buffer.from(whole.indices.buffer)) === 0,
      "in pieces: the same vertex and index bytes as whole");
if (failed()) process.exit(1);
console.log(`ok ${progressivePath}: ${layout.insertions} records, ${layout.faceCount} faces`);
