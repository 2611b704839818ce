// Reads a vrsimplify levels-of-detail .glb level by level, coarsest first, through HTTP range
// requests (or slices of a dropped file): the header and JSON first, then for each level only
// the vertices it adds to the shared prefix and its own indices. No three.js here: the viewer
// turns each level into geometry.

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
    return {
      name: mesh.name,
      extras: mesh.extras?.vrsimplify ?? {},
      vertices: position.count,
      faces: index.count / 3,
      indexStart: binStart + (indexView.byteOffset ?? 0) + (index.byteOffset ?? 0),
      indexBytes: index.count * (index.componentType === 5125 ? 4 : 2),
      indexType: index.componentType,
      attributes: Object.fromEntries(Object.entries(prim.attributes).map(([k, a]) => {
        const acc = json.accessors[a];
        return [k, { offset: acc.byteOffset ?? 0, type: acc.type, componentType: acc.componentType,
                     normalized: !!acc.normalized, min: acc.min, max: acc.max }];
      })),
    };
  });
  const finest = json.accessors[json.meshes[json.nodes[nodeIds[0]].mesh].primitives[0].attributes.POSITION];
  const vertexView = json.bufferViews[finest.bufferView];
  return {
    levels,
    vertexStart: binStart + (vertexView.byteOffset ?? 0),
    stride: vertexView.byteStride ?? 12,
    image: json.images?.[0]?.uri,
    coverage: node.extras?.MSFT_screencoverage,
  };
}

// Streams the levels coarsest first: onLevel({level, index, vertexBytes, indices, layout})
// gets the whole vertex prefix so far (one growing buffer) and that level's indices.
export async function streamLevels(source, onLevel, { stopAfter } = {}) {
  const head = new DataView(await source.read(0, 20));
  if (head.getUint32(0, true) !== GLB_MAGIC) throw new Error("not a binary glTF (.glb)");
  const total = head.getUint32(8, true);
  const jsonBytes = head.getUint32(12, true);
  const jsonText = new TextDecoder().decode(await source.read(20, 20 + jsonBytes + 8));
  const json = JSON.parse(jsonText.slice(0, jsonBytes));
  const layout = describe(json, 20 + jsonBytes + 8);
  layout.total = total;
  layout.json = json;
  const vertices = new Uint8Array(layout.levels[0].vertices * layout.stride);
  let have = 0; // vertices received so far
  for (let k = layout.levels.length - 1; k >= 0; --k) {
    const level = layout.levels[k];
    const want = level.vertices * layout.stride;
    let indexBuffer;
    // The coarsest level's indices lie just before the vertices: one request for both.
    if (k === layout.levels.length - 1 && level.indexStart + level.indexBytes === layout.vertexStart) {
      const both = new Uint8Array(await source.read(level.indexStart, layout.vertexStart + want));
      vertices.set(both.subarray(level.indexBytes), 0);
      indexBuffer = both.slice(0, level.indexBytes).buffer;
    } else {
      const [added, idx] = await Promise.all([
        source.read(layout.vertexStart + have, layout.vertexStart + want),
        source.read(level.indexStart, level.indexStart + level.indexBytes),
      ]);
      vertices.set(new Uint8Array(added), have);
      indexBuffer = idx;
    }
    have = Math.max(have, want);
    const indices = level.indexType === 5125 ? new Uint32Array(indexBuffer) : new Uint16Array(indexBuffer);
    await onLevel({ level, index: k, vertices: vertices.subarray(0, want), indices, layout });
    if (stopAfter !== undefined && k <= stopAfter) break;
  }
  return layout;
}
