// Reads a vrsimplify levels-of-detail .glb level by level, coarsest first, through HTTP range
// requests (or slices of a dropped file): the header and JSON first, then for each level only
// the vertices it adds to the shared prefix and its own indices. No three.js here: the viewer
// turns each level into geometry. A file with EXT_meshopt_compression streams the same way:
// each level's vertices end on a block of the vertex codec, so the compressed stream's first
// bytes and its tail (kept in the JSON) decode that prefix alone (gltf/src/meshopt_streams.h);
// the caller hands in meshoptimizer's decoder.

const GLB_MAGIC = 0x46546c67;

// Byte ranges of a URL (Range requests; a server that ignores them sends the whole file,
// which still works, only later) or of a File/Blob.
export class RangeSource {
  constructor(source, onBytes) {
    this.source = source;
    this.onBytes = onBytes ?? (() => {});
    this.received = 0;
  }
  async read(start, end) { // [start, end)
    if (end <= start) return new ArrayBuffer(0);
    let buffer;
    if (typeof this.source === "string") {
      const response = await fetch(this.source, { headers: { Range: `bytes=${start}-${end - 1}` } });
      if (!response.ok) throw new Error(`${this.source}: HTTP ${response.status}`);
      buffer = await response.arrayBuffer();
      if (response.status === 200) buffer = buffer.slice(start, end); // no range support
    } else {
      buffer = await this.source.slice(start, end).arrayBuffer();
    }
    this.received += buffer.byteLength;
    this.onBytes(this.received);
    return buffer;
  }
}

// The file's layout from its JSON: per level (finest first) its vertex count, faces, index
// range and type, and the shared vertex view with its attributes.
export function describe(json, binStart) {
  const top = json.scenes[json.scene ?? 0].nodes[0];
  const node = json.nodes[top];
  const nodeIds = [top, ...(node.extensions?.MSFT_lod?.ids ?? [])];
  const levels = nodeIds.map((n) => {
    const mesh = json.meshes[json.nodes[n].mesh];
    const prim = mesh.primitives[0];
    const position = json.accessors[prim.attributes.POSITION];
    const index = json.accessors[prim.indices];
    const indexView = json.bufferViews[index.bufferView];
    const packed = indexView.extensions?.EXT_meshopt_compression; // its bytes in the file
    return {
      name: mesh.name,
      extras: mesh.extras?.vrsimplify ?? {},
      vertices: position.count,
      faces: index.count / 3,
      indexStart: binStart + (packed ? packed.byteOffset ?? 0 : (indexView.byteOffset ?? 0) + (index.byteOffset ?? 0)),
      indexBytes: packed ? packed.byteLength : index.count * (index.componentType === 5125 ? 4 : 2),
      indexType: index.componentType,
      indexCount: index.count,
      attributes: Object.fromEntries(Object.entries(prim.attributes).map(([k, a]) => {
        const acc = json.accessors[a];
        return [k, { offset: acc.byteOffset ?? 0, type: acc.type, componentType: acc.componentType,
                     normalized: !!acc.normalized, min: acc.min, max: acc.max }];
      })),
    };
  });
  const finest = json.accessors[json.meshes[json.nodes[nodeIds[0]].mesh].primitives[0].attributes.POSITION];
  const vertexView = json.bufferViews[finest.bufferView];
  const packed = vertexView.extensions?.EXT_meshopt_compression;
  const tail = vertexView.extras?.vrsimplify?.tail;
  return {
    levels,
    // Compressed: where the stream lies, its tail, and each level's bytes of it.
    compressed: packed && {
      bytes: packed.byteLength,
      tail: tail && Uint8Array.from(atob(tail), (c) => c.charCodeAt(0)),
    },
    vertexStart: binStart + (packed ? packed.byteOffset ?? 0 : vertexView.byteOffset ?? 0),
    stride: vertexView.byteStride ?? 12,
    image: json.images?.[0]?.uri,
    coverage: node.extras?.MSFT_screencoverage,
  };
}

// Streams the levels coarsest first: onLevel({level, index, vertexBytes, indices, layout})
// gets the whole vertex prefix so far (one growing buffer) and that level's indices.
// `decoder`: meshoptimizer's (three/addons/libs/meshopt_decoder.module.js), for compressed files.
export async function streamLevels(source, onLevel, { stopAfter, decoder } = {}) {
  const head = new DataView(await source.read(0, 20));
  if (head.getUint32(0, true) !== GLB_MAGIC) throw new Error("not a binary glTF (.glb)");
  const total = head.getUint32(8, true);
  const jsonBytes = head.getUint32(12, true);
  const jsonText = new TextDecoder().decode(await source.read(20, 20 + jsonBytes + 8));
  const json = JSON.parse(jsonText.slice(0, jsonBytes));
  const layout = describe(json, 20 + jsonBytes + 8);
  layout.total = total;
  layout.json = json;
  const packed = layout.compressed;
  if (packed && !decoder) throw new Error("a compressed .glb (EXT_meshopt_compression) needs meshoptimizer's decoder");
  if (packed && !packed.tail) throw new Error("this compressed .glb cannot stream (no tail of its vertex stream in the JSON)");
  if (packed) await decoder.ready;
  // The vertex data as received so far: the plain records, or the compressed stream's bytes.
  const data = new Uint8Array(packed ? packed.bytes : layout.levels[0].vertices * layout.stride);
  let have = 0; // bytes of it received so far
  for (let k = layout.levels.length - 1; k >= 0; --k) {
    const level = layout.levels[k];
    // The bytes of the vertex data that hold this level's prefix (compressed: without the
    // tail, which the JSON holds).
    const want = !packed ? level.vertices * layout.stride
      : k === 0 ? packed.bytes - packed.tail.length : level.extras.streamBytes;
    if (!(want > 0)) throw new Error(`level ${k} does not say which bytes of the vertex stream hold it`);
    let indexBytes;
    // The coarsest level's indices lie just before the vertex data (compressed: up to 3 bytes
    // of padding between): one request for both.
    const gap = layout.vertexStart - (level.indexStart + level.indexBytes);
    if (k === layout.levels.length - 1 && gap >= 0 && gap < (packed ? 4 : 1)) {
      const both = new Uint8Array(await source.read(level.indexStart, layout.vertexStart + want));
      data.set(both.subarray(level.indexBytes + gap), 0);
      indexBytes = both.slice(0, level.indexBytes);
    } else {
      const [added, idx] = await Promise.all([
        want > have ? source.read(layout.vertexStart + have, layout.vertexStart + want) : new ArrayBuffer(0),
        source.read(level.indexStart, level.indexStart + level.indexBytes),
      ]);
      data.set(new Uint8Array(added), have);
      indexBytes = new Uint8Array(idx);
    }
    have = Math.max(have, want);
    const wide = level.indexType === 5125;
    let vertices = data.subarray(0, want), raw = indexBytes;
    if (packed) {
      // The prefix's bytes with the tail appended are a valid stream of that prefix.
      const prefix = new Uint8Array(want + packed.tail.length);
      prefix.set(data.subarray(0, want), 0);
      prefix.set(packed.tail, want);
      vertices = new Uint8Array(level.vertices * layout.stride);
      decoder.decodeVertexBuffer(vertices, level.vertices, layout.stride, prefix);
      raw = new Uint8Array(level.indexCount * (wide ? 4 : 2));
      decoder.decodeIndexBuffer(raw, level.indexCount, wide ? 4 : 2, indexBytes);
    }
    const indices = wide ? new Uint32Array(raw.buffer) : new Uint16Array(raw.buffer);
    await onLevel({ level, index: k, vertices, indices, layout });
    if (stopAfter !== undefined && k <= stopAfter) break;
  }
  return layout;
}
