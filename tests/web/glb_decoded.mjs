// A compressed levels-of-detail .glb against the same levels written uncompressed, decoded with
// meshoptimizer's own decoder (the one three.js ships):
//   - every level holds the same triangles, each corner the same vertex record bit for bit
//     (positions, normals, colors, texture coordinates): the compression is lossless; triangle
//     and vertex order may differ, and the index codec may start a triangle at another corner;
//   - each coarser level decodes alone from the first bytes of the vertex stream its mesh names
//     and the stream's tail (what the viewer page does while the rest is on its way), giving the
//     same records as the whole stream.
//   node tests/web/glb_decoded.mjs PLAIN.glb COMPRESSED.glb
import { readFileSync } from "node:fs";
import { MeshoptDecoder } from "../../web/node_modules/three/examples/jsm/libs/meshopt_decoder.module.js";
import { checks } from "./checks.mjs";

const [plainPath, packedPath] = process.argv.slice(2);
const { check, failed } = checks();

function parse(path) {
  const b = readFileSync(path);
  const jsonBytes = b.readUInt32LE(12);
  const json = JSON.parse(b.subarray(20, 20 + jsonBytes).toString());
  const bin = b.subarray(20 + jsonBytes + 8);
  const top = json.scenes[json.scene ?? 0].nodes[0];
  const nodes = [top, ...(json.nodes[top].extensions?.MSFT_lod?.ids ?? [])];
  return { json, bin, meshes: nodes.map((n) => json.meshes[json.nodes[n].mesh]) };
}

// The bytes of a view, decoded when compressed.
function viewBytes(file, index) {
  const view = file.json.bufferViews[index];
  const ext = view.extensions?.EXT_meshopt_compression;
  if (!ext) return file.bin.subarray(view.byteOffset ?? 0, (view.byteOffset ?? 0) + view.byteLength);
  const out = new Uint8Array(ext.count * ext.byteStride);
  const src = file.bin.subarray(ext.byteOffset ?? 0, (ext.byteOffset ?? 0) + ext.byteLength);
  if (ext.mode === "ATTRIBUTES") MeshoptDecoder.decodeVertexBuffer(out, ext.count, ext.byteStride, src);
  else MeshoptDecoder.decodeIndexBuffer(out, ext.count, ext.byteStride, src);
  return out;
}

// One level's triangles as strings of their corners' records, each started at its smallest
// corner (winding kept), sorted.
function triangles(file, mesh) {
  const prim = mesh.primitives[0];
  const pos = file.json.accessors[prim.attributes.POSITION];
  const stride = file.json.bufferViews[pos.bufferView].byteStride;
  const vertices = viewBytes(file, pos.bufferView);
  const idx = file.json.accessors[prim.indices];
  const raw = viewBytes(file, idx.bufferView);
  const ids = idx.componentType === 5125 ? new Uint32Array(raw.buffer, raw.byteOffset, idx.count)
                                         : new Uint16Array(raw.buffer, raw.byteOffset, idx.count);
  const rec = (v) => Buffer.from(vertices.subarray(v * stride, (v + 1) * stride)).toString("hex");
  const out = [];
  for (let t = 0; t < ids.length; t += 3) {
    const c = [rec(ids[t]), rec(ids[t + 1]), rec(ids[t + 2])];
    const m = c.indexOf([...c].sort()[0]);
    out.push([c[m], c[(m + 1) % 3], c[(m + 2) % 3]].join("|"));
  }
  return out.sort();
}

await MeshoptDecoder.ready;
const plain = parse(plainPath), packed = parse(packedPath);
check(plain.meshes.length === packed.meshes.length, "the same number of levels");
for (let k = 0; k < plain.meshes.length; ++k) {
  const a = triangles(plain, plain.meshes[k]), b = triangles(packed, packed.meshes[k]);
  check(a.length === b.length && a.every((x, i) => x === b[i]), `level ${k}: the same triangles, the same vertex records`);
}
// Each level's prefix of the stream, with the tail, decodes alone.
const vertexView = packed.json.bufferViews[packed.json.accessors[packed.meshes[0].primitives[0].attributes.POSITION].bufferView];
const ext = vertexView.extensions.EXT_meshopt_compression;
const tail = Buffer.from(vertexView.extras.vrsimplify.tail, "base64");
const whole = viewBytes(packed, packed.json.bufferViews.indexOf(vertexView));
const stream = packed.bin.subarray(ext.byteOffset, ext.byteOffset + ext.byteLength);
check(Buffer.compare(tail, stream.subarray(stream.length - tail.length)) === 0, "the tail in the JSON is the stream's");
for (let k = 1; k < packed.meshes.length; ++k) {
  const count = packed.json.accessors[packed.meshes[k].primitives[0].attributes.POSITION].count;
  const bytes = packed.meshes[k].extras.vrsimplify.streamBytes;
  const prefix = Buffer.concat([stream.subarray(0, bytes), tail]);
  const out = new Uint8Array(count * ext.byteStride);
  let ok = true;
  try {
    MeshoptDecoder.decodeVertexBuffer(out, count, ext.byteStride, prefix);
  } catch (e) {
    ok = false;
  }
  check(ok && Buffer.compare(Buffer.from(out), Buffer.from(whole.subarray(0, out.length))) === 0,
        `level ${k}: its ${bytes} bytes of the stream decode alone to the stream's first ${count} vertices`);
}
console.log(failed() ? `${failed()} failed` : "ok: the compressed levels are the plain ones, and stream");
process.exit(failed() ? 1 : 0);
