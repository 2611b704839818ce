// A progressive .glb (docs/progressive.md) in the browser: the base mesh, then one insertion
// record a vertex, applied as the bytes arrive. ProgressiveDecoder keeps the vertex bytes and
// the indices in arrays sized for the whole mesh and says which ranges each step changed (no
// three.js here); streamProgressive reads a URL, its base first and then the records streamed;
// VRSProgressivePlugin does the same for three.js's GLTFLoader when it loaded the whole file.

export const EXTENSION = "VRS_mesh_progressive";
const CLOSED_FAN = 1, OPEN_FAN = 2, LISTED_RING = 3;
const RICE_ESCAPE = 16, RICE_SPREAD_SHIFT = 3; // docs/progressive.md, "the vertices"
const POWERS_OF_TWO = Float64Array.from({ length: 64 }, (_, i) => 2 ** i);

// The JSON chunk and where the binary chunk starts, once the first bytes are in (null before).
export function readHeader(bytes) {
  if (bytes.length < 20) return null;
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  if (view.getUint32(0, true) !== 0x46546c67) throw new Error("not a binary glTF file");
  const jsonLength = view.getUint32(12, true);
  if (bytes.length < 20 + jsonLength + 8) return null;
  const json = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLength)));
  return { json, binStart: 20 + jsonLength + 8 };
}

// The progressive primitive's layout: its base's vertex and index ranges in the binary chunk,
// the stride, the attributes, the records' view and the whole mesh's counts.
export function describeProgressive(json) {
  const prim = json.meshes?.[0]?.primitives?.[0];
  const ext = prim?.extensions?.[EXTENSION];
  if (!ext) return null;
  const position = json.accessors[prim.attributes.POSITION];
  const vertexView = json.bufferViews[position.bufferView];
  const index = json.accessors[prim.indices];
  const indexView = json.bufferViews[index.bufferView];
  const recordView = json.bufferViews[ext.bufferView];
  return {
    version: ext.version,
    stride: vertexView.byteStride,
    baseVertices: position.count,
    baseIndices: index.count,
    vertexStart: vertexView.byteOffset ?? 0,
    indexStart: (indexView.byteOffset ?? 0) + (index.byteOffset ?? 0),
    indexType: index.componentType,
    recordStart: recordView.byteOffset ?? 0,
    recordBytes: recordView.byteLength,
    insertions: ext.insertions,
    vertexCount: ext.vertexCount,
    faceCount: ext.faceCount,
    min: position.min,
    max: position.max,
    attributes: Object.fromEntries(Object.entries(prim.attributes).map(([k, a]) => {
      const acc = json.accessors[a];
      return [k, { offset: acc.byteOffset ?? 0, type: acc.type, componentType: acc.componentType,
                   normalized: !!acc.normalized }];
    })),
    image: json.images?.[0]?.uri,
  };
}

const nextSide = (s) => (s % 3 === 2 ? s - 2 : s + 1);
const distinct = (a, n, below) => {
  for (let i = 0; i < n; i++) {
    if (a[i] >= below) return false;
    for (let j = 0; j < i; j++) if (a[i] === a[j]) return false;
  }
  return true;
};
// The Rice parameter of a value whose known vertices lie up to `spread` (< 2^33) from its
// prediction: the spread's bit length less RICE_SPREAD_SHIFT.
const riceParameter = (spread) => Math.max(0,
  (spread < 2 ** 31 ? 32 - Math.clz32(spread) : spread < 2 ** 32 ? 32 : 33) - RICE_SPREAD_SHIFT);
// A float's bits as an integer that orders the floats as their values do; its own inverse.
const ordered = (b) => (b < 0 ? b ^ 0x7fffffff : b);
const faceOf = (side) => (side - (side % 3)) / 3;
const holds = (slots, n, face) => { // whether slots[0, n) holds `face`
  for (let j = 0; j < n; j++) if (slots[j] === face) return true;
  return false;
};
const unzigzag = (z) => ((z & 1) === 0 ? z / 2 : -(z + 1) / 2); // z & 1: its low bit, any size

export class ProgressiveDecoder {
  // `binary`: the binary chunk's bytes so far (at least the base's).
  constructor(layout, binary) {
    if (layout.version !== 3)
      throw new Error(`a ${EXTENSION} stream of version ${layout.version}: this reader knows version 3`);
    this.layout = layout;
    const { stride, baseVertices, baseIndices } = layout;
    this.vertices = new Uint8Array(layout.vertexCount * stride);
    this.vertices.set(binary.subarray(layout.vertexStart, layout.vertexStart + baseVertices * stride));
    this.floats = new Float32Array(this.vertices.buffer);
    this.ints = new Int32Array(this.vertices.buffer);
    this.indices = new Uint32Array(layout.faceCount * 3);
    const wide = layout.indexType === 5125;
    const src = binary.slice(layout.indexStart, layout.indexStart + baseIndices * (wide ? 4 : 2)).buffer;
    this.indices.set(wide ? new Uint32Array(src) : new Uint16Array(src));
    // The faces' corners are the index buffer; beside it, for each side (3 * face + c, from
    // corner c to c + 1), the side across it, -1 for none: the base's sides paired by the base
    // rule (docs/progressive.md).
    const X = (this.across = new Int32Array(layout.faceCount * 3));
    const waiting = new Map(), idx = this.indices, V = layout.vertexCount;
    X.fill(-1, 0, baseIndices);
    for (let s = 0; s < baseIndices; s++) {
      const a = idx[s], b = idx[nextSide(s)];
      const t = waiting.get(b * V + a);
      if (t !== undefined) {
        X[s] = t;
        X[t] = s;
        waiting.delete(b * V + a);
      } else if (!waiting.has(a * V + b)) waiting.set(a * V + b, s);
    }
    // The vertex values in coding order, flat: offset (in floats or bytes), count, 1 for floats.
    const at = (name) => layout.attributes[name]?.offset;
    const groups = [0, 3, 1];
    if (at("NORMAL") !== undefined) groups.push(at("NORMAL") / 4, 3, 1);
    if (at("COLOR_0") !== undefined) groups.push(at("COLOR_0"), 4, 0);
    if (at("TEXCOORD_0") !== undefined) groups.push(at("TEXCOORD_0") / 4, 2, 1);
    this.groups = Int32Array.from(groups);
    this.vertexCount = baseVertices;
    this.faceCount = baseIndices / 3;
    this.applied = 0;
    this.previousFirst = 0;
    this.records = new Uint8Array(layout.recordBytes);
    this.received = 0; // record bytes in
    this.at = 0; // the next record's offset
    this.p = 0; // the reading position within a record (applyOne), in bytes
    this.bitAt = 0; // and in bits of that byte, within the record's run of bits
    this.added = 0; // the record's new vertices and patch corners (vertex())
    this.corners = 0;
    this.scratch = null;
    this.resetChanges();
  }

  // Bytes of the records' view, in order.
  push(chunk) {
    const n = Math.min(chunk.length, this.records.length - this.received);
    this.records.set(chunk.subarray(0, n), this.received);
    this.received += n;
  }

  get complete() {
    return this.applied >= this.layout.insertions;
  }

  // What changed since the last resetChanges(): vertices [vertexFrom, vertexCount), indices
  // [indexLow, indexHigh).
  resetChanges() {
    this.vertexFrom = this.vertexCount;
    this.indexLow = Infinity;
    this.indexHigh = 0;
  }

  // Applies whole records until `deadline` (performance.now()), `most` of them, or the bytes
  // run out; returns how many.
  apply(deadline = Infinity, most = Infinity) {
    let count = 0;
    while (!this.complete && count < most) {
      if ((count & 63) === 0 && performance.now() > deadline) break;
      const next = this.applyOne(this.at);
      if (next < 0) break;
      this.at = next;
      this.applied++;
      count++;
    }
    return count;
  }

  // A varint at this.p (-1: its bytes are not all in).
  varint() {
    const r = this.records, end = this.received;
    let value = 0, scale = 1;
    for (;;) {
      if (this.p >= end) return -1;
      const b = r[this.p++];
      value += (b & 0x7f) * scale;
      if (b < 0x80) return value;
      scale *= 128;
    }
  }

  // The vertex reference `ref` names (docs/progressive.md).
  vertex(ref) {
    const added = this.added, corners = this.corners, V = this.vertexCount;
    return ref < added ? V + ref
      : ref < added + corners ? this.scratch.patch[ref - added]
      : V - 1 - (ref - added - corners);
  }

  // The record's run of bits (docs/progressive.md), lowest bit of each byte first, read from
  // byte this.p, bit this.bitAt: the next bit, or -1 when its byte is not in.
  bit() {
    if (this.p >= this.received) return -1;
    const b = (this.records[this.p] >> this.bitAt) & 1;
    if (++this.bitAt === 8) {
      this.bitAt = 0;
      this.p++;
    }
    return b;
  }

  // The next n bits as a number, the first the lowest (-1: not all in).
  bitsOf(n) {
    if (n === 0) return 0;
    if (this.p + ((this.bitAt + n - 1) >> 3) >= this.received) return -1;
    const r = this.records;
    let value = 0, scale = 1;
    while (n > 0) {
      const take = Math.min(8 - this.bitAt, n);
      value += ((r[this.p] >> this.bitAt) & ((1 << take) - 1)) * scale;
      scale *= 1 << take;
      n -= take;
      if ((this.bitAt += take) === 8) {
        this.bitAt = 0;
        this.p++;
      }
    }
    return value;
  }

  // A Rice code of parameter k: ones and a zero, then k bits; 16 ones escape to a bit length
  // (6 bits) and that many bits. -1: not all in.
  rice(k) {
    const p = this.p;
    if (p + 4 < this.received) { // the ones from a window of 25 bits or more
      const r = this.records, at = this.bitAt;
      const w = (r[p] | (r[p + 1] << 8) | (r[p + 2] << 16) | (r[p + 3] << 24)) >>> at;
      const zeros = ~w, q = 31 - Math.clz32(zeros & -zeros); // w's lowest zero
      const ones = at + q + 1;
      if (q >= 0 && q < RICE_ESCAPE && ones <= 32) {
        if (k <= 24 && ones + k <= 32) {
          this.p = p + ((ones + k) >> 3);
          this.bitAt = (ones + k) & 7;
          return (q << k) | ((w >>> (q + 1)) & ((1 << k) - 1));
        }
        this.p = p + (ones >> 3);
        this.bitAt = ones & 7;
        const low = this.bitsOf(k);
        return low < 0 ? -1 : q * POWERS_OF_TWO[k] + low;
      }
    }
    let q = 0;
    for (;;) {
      const b = this.bit();
      if (b < 0) return -1;
      if (b === 0) break;
      if (++q === RICE_ESCAPE) {
        const length = this.bitsOf(6);
        return length < 0 ? -1 : this.bitsOf(length);
      }
    }
    const low = this.bitsOf(k);
    return low < 0 ? -1 : q * POWERS_OF_TWO[k] + low;
  }

  // The patch walked from face `first` (docs/progressive.md), steered by the record's bits:
  // its faces into `slots`; false when the bits are not all in.
  walk(first, count, slots) {
    const X = this.across;
    let n = 1;
    slots[0] = first;
    for (let i = 0; n < count; i++) {
      if (i === n) throw new Error("a record's patch walk ends early: not a stream this reads");
      for (let c = 0; c < 3 && n < count; c++) {
        const t = X[3 * slots[i] + c];
        if (t < 0) continue;
        const q = faceOf(t);
        if (holds(slots, n, q)) continue;
        const b = this.bit();
        if (b < 0) return false;
        if (b) slots[n++] = q;
      }
    }
    return true;
  }

  // One record at `at`: the offset after it, or -1 when its bytes are not all in. Scratch
  // arrays, no allocation: a record is a few dozen bytes and there are millions.
  applyOne(at) {
    const stride = this.layout.stride;
    const s = this.scratch ?? (this.scratch = {
      slots: new Int32Array(256), patch: new Int32Array(768), ring: new Int32Array(260),
      faces: new Int32Array(768), from: new Int32Array(768), to: new Int32Array(768),
      outer: new Int32Array(4 * 768), sides: new Int32Array(768), known: new Int32Array(768),
      outside: new Int32Array(768), edge: new Int32Array(260), refs: new Int32Array(768),
      bits: new Int32Array(1) });
    s.asFloat ??= new Float32Array(s.bits.buffer); // a float's bits, through s.bits
    this.p = at;
    const head = this.varint();
    if (head < 0) return -1;
    const k = Math.floor(head / 16), listed = (head >> 3) & 1, shape = (head >> 1) & 3;
    let added = 1, apexRef = 0;
    if (head & 1) {
      if ((added = this.varint()) < 0) return -1;
      if (shape && (apexRef = this.varint()) < 0) return -1;
    }
    if (k > 256 || added > 256) throw new Error(`a record of ${k} faces: not a progressive stream this reads`);
    const reused = shape === CLOSED_FAN ? k - 2 : shape === OPEN_FAN ? k - 1 : this.varint();
    if (reused < 0) return -1;
    if (reused > k) throw new Error(`a record replacing ${reused} faces with ${k}: not a progressive stream this reads`);
    const F = this.faceCount, X = this.across, idx = this.indices;
    const { slots, patch, ring, faces, from, to, outside, edge, refs } = s;
    // First the record's numbers, then its run of bits: the walk's steering, the vertices.
    let first = this.previousFirst;
    if (listed) {
      for (let i = 0; i < reused; i++) {
        const back = this.varint();
        if (back < 0) return -1;
        slots[i] = F - 1 - back;
      }
    } else {
      const step = this.varint();
      if (step < 0) return -1;
      first += unzigzag(step);
    }
    let start = 0, open = 0, refCount = 0;
    if (shape === OPEN_FAN && (start = this.varint()) < 0) return -1;
    if (shape === LISTED_RING && (open = this.varint()) < 0) return -1;
    if (shape === LISTED_RING || shape === 0) {
      refCount = shape === LISTED_RING ? k + open : 3 * k;
      if (refCount > refs.length) throw new Error("a record's ring is too long: not a progressive stream this reads");
      for (let i = 0; i < refCount; i++)
        if ((refs[i] = this.varint()) < 0) return -1;
    }
    this.bitAt = 0;
    if (!listed && !this.walk(first, reused, slots)) return -1;
    for (let i = 0; i < reused; i++) {
      const slot = slots[i];
      patch[3 * i] = idx[3 * slot];
      patch[3 * i + 1] = idx[3 * slot + 1];
      patch[3 * i + 2] = idx[3 * slot + 2];
    }
    const corners = 3 * reused;
    this.added = added;
    this.corners = corners;
    let length = 0; // the ring's
    if (shape === CLOSED_FAN || shape === OPEN_FAN) {
      // The patch's outline: its sides with no patch face across, in the patch's order.
      let sides = 0;
      for (let i = 0, t = 0; i < reused; i++)
        for (let c = 0; c < 3; c++, t++) {
          const across = X[3 * slots[i] + c];
          if (across >= 0 && holds(slots, reused, faceOf(across))) continue;
          from[sides] = patch[t];
          to[sides] = patch[nextSide(t)];
          outside[sides++] = across;
        }
      length = shape === CLOSED_FAN ? k : k + 1;
      ring[0] = from[start];
      // Each fan side's outline side (edge[i]: from ring[i] to ring[i + 1]), for writeFaces.
      for (let n = 1; n <= k; n++) {
        const a = ring[n - 1];
        let i = 0;
        while (i < sides && from[i] !== a) i++;
        edge[n - 1] = i;
        if (n < length) ring[n] = to[i];
      }
      this.outlineSides = sides;
    } else if (shape === LISTED_RING) {
      length = refCount;
      for (let i = 0; i < length; i++) ring[i] = this.vertex(refs[i]);
    } else {
      for (let i = 0; i < 3 * k; i++) faces[i] = this.vertex(refs[i]);
    }
    if (shape) {
      const apex = this.vertex(apexRef);
      for (let i = 0; i < k; i++) {
        faces[3 * i] = apex;
        faces[3 * i + 1] = ring[i];
        faces[3 * i + 2] = ring[i + 1 < length ? i + 1 : 0];
      }
    }
    // A fan around its one new vertex, with a ring of distinct older vertices, takes shortcuts.
    const V = this.vertexCount;
    const fan = (shape === CLOSED_FAN || shape === OPEN_FAN) && added === 1 && faces[0] === V &&
      distinct(ring, length, V);
    if (!this.readVertices(added, k, fan ? length : 0)) return -1;
    // Whole: write it.
    if (!listed) this.previousFirst = first;
    this.vertexCount += added;
    this.writeFaces(reused, k, fan, length === k);
    return this.bitAt ? this.p + 1 : this.p;
  }

  // The record's new vertices, each value its prediction (the mean of the older vertices its
  // faces touch) plus a residual; false when their bytes are not all in. They go into the
  // vertex buffer past the vertices drawn, so a record not whole changes nothing drawn.
  readVertices(added, k, fanRing) {
    const { faces, known, bits, asFloat } = this.scratch, stride = this.layout.stride, w = stride / 4;
    const V = this.vertexCount, f32 = this.floats, i32 = this.ints, u8 = this.vertices;
    const groups = this.groups;
    for (let j = 0; j < added; j++) {
      const v = V + j;
      let n = 0;
      if (fanRing > 0) { // a fan's apex: its ring, distinct vertices, all older
        for (; n < fanRing; n++) known[n] = this.scratch.ring[n];
      } else for (let i = 0; i < 3 * k; i += 3) {
        if (faces[i] !== v && faces[i + 1] !== v && faces[i + 2] !== v) continue;
        for (let c = 0; c < 3; c++) {
          const u = faces[i + c];
          if (u >= V) continue;
          let seen = false;
          for (let q = 0; q < n && !seen; q++) seen = known[q] === u;
          if (!seen) known[n++] = u;
        }
      }
      // Each value: its prediction, how far the known vertices lie from it (the Rice code's
      // parameter: the farther of their least and greatest), its residual.
      for (let g = 0; g < groups.length; g += 3)
        for (let c = 0, o = groups[g], isFloat = groups[g + 2]; c < groups[g + 1]; c++, o++) {
          let predicted = 0, spread = 0;
          if (isFloat) {
            if (n) {
              let sum = 0, low = Infinity, high = -Infinity;
              for (let q = 0; q < n; q++) {
                const at = known[q] * w + o, x = ordered(i32[at]);
                sum += f32[at];
                low = Math.min(low, x);
                high = Math.max(high, x);
              }
              asFloat[0] = sum / n;
              predicted = ordered(bits[0]);
              spread = Math.max(high - predicted, predicted - low);
            } else {
              predicted = ordered(j ? i32[(v - 1) * w + o] : 0);
            }
            const z = this.rice(riceParameter(spread));
            if (z < 0) return false;
            i32[v * w + o] = ordered(predicted + unzigzag(z));
          } else {
            if (n) {
              let sum = 0, low = 255, high = 0;
              for (let q = 0; q < n; q++) {
                const x = u8[known[q] * stride + o];
                sum += x;
                if (x < low) low = x;
                if (x > high) high = x;
              }
              predicted = Math.floor(sum / n + 0.5);
              spread = Math.max(high - predicted, predicted - low);
            } else if (j) predicted = u8[(v - 1) * stride + o];
            const z = this.rice(riceParameter(spread));
            if (z < 0) return false;
            u8[v * stride + o] = (predicted + unzigzag(z)) & 0xff;
          }
        }
    }
    return true;
  }

  // The record's k faces into the patch's slots, the rest appended; their sides paired by the
  // record rule (docs/progressive.md).
  writeFaces(reused, k, fan, closed) {
    const s = this.scratch, { slots, faces, outer, sides } = s, idx = this.indices, X = this.across;
    let outerCount = 0;
    if (fan) // the outline's sides across lose their pairing, as outer sides do below
      for (let e = 0; e < this.outlineSides; e++) if (s.outside[e] >= 0) X[s.outside[e]] = -1;
    for (let i = 0; i < reused && !fan; i++)
      for (let c = 0; c < 3; c++) {
        const side = 3 * slots[i] + c, t = X[side];
        if (t < 0 || holds(slots, reused, faceOf(t))) continue;
        outer[4 * outerCount] = idx[side];
        outer[4 * outerCount + 1] = idx[nextSide(side)];
        outer[4 * outerCount + 2] = t;
        outer[4 * outerCount + 3] = 0;
        outerCount++;
        X[t] = -1;
      }
    for (let i = 0; i < k; i++) {
      const slot = i < reused ? slots[i] : this.faceCount++;
      for (let c = 0; c < 3; c++) {
        idx[3 * slot + c] = faces[3 * i + c];
        X[3 * slot + c] = -1;
        sides[3 * i + c] = 3 * slot + c;
      }
      if (3 * slot < this.indexLow) this.indexLow = 3 * slot;
      if (3 * slot + 3 > this.indexHigh) this.indexHigh = 3 * slot + 3;
    }
    if (fan) {
      // A fan around a new apex with a ring of distinct vertices: the record rule pairs each
      // face with its neighbours in the fan and its outline side with the side across that
      // outline side (the same pairs, found without searching).
      for (let i = 0; i < k; i++) {
        const side = sides[3 * i + 1], t = s.outside[s.edge[i]];
        X[side] = t;
        if (t >= 0) X[t] = side;
        if (i + 1 < k || closed) {
          const next = sides[i + 1 < k ? 3 * i + 3 : 0], mine = sides[3 * i + 2];
          X[mine] = next;
          X[next] = mine;
        }
      }
      return;
    }
    const n = 3 * k;
    for (let i = 0; i < n; i++) {
      const side = sides[i];
      if (X[side] >= 0) continue;
      const a = idx[side], b = idx[nextSide(side)];
      let paired = false;
      for (let o = 0; o < outerCount; o++)
        if (!outer[4 * o + 3] && outer[4 * o] === a && outer[4 * o + 1] === b) {
          outer[4 * o + 3] = 1;
          X[side] = outer[4 * o + 2];
          X[outer[4 * o + 2]] = side;
          paired = true;
          break;
        }
      for (let j = i + 1; j < n && !paired; j++) {
        const t = sides[j];
        if (X[t] < 0 && idx[t] === b && idx[nextSide(t)] === a) {
          X[side] = t;
          X[t] = side;
          paired = true;
        }
      }
    }
  }
}

// Reads `url`: calls onBase(decoder) once the base's bytes are in, then onBytes(received,
// total) as more arrive; the records are pushed into the decoder, which the caller applies (per
// frame, say). Where the server takes range requests, the header and the base come first, by
// themselves, and then the records in one streamed GET: a browser hands a streamed response
// over several chunks at a time, and the base waited for bytes past its own. Elsewhere the
// whole file is one streamed GET.
export async function streamProgressive(url, { onBase, onBytes = () => {} }) {
  const kFirst = 1 << 14; // the first range: the header, and a small file's whole base
  let buffer = null, length = 0, total = 0; // sized once the total is known
  let header = null, layout = null, decoder = null, fed = 0;
  const take = (value) => {
    if (length + value.length > buffer.length) {
      const grown = new Uint8Array(Math.max(2 * buffer.length, length + value.length));
      grown.set(buffer.subarray(0, length));
      buffer = grown;
    }
    buffer.set(value, length);
    length += value.length;
    onBytes(length, total);
    if (!header && (header = readHeader(buffer.subarray(0, length)))) {
      layout = describeProgressive(header.json);
      if (!layout) throw new Error(`${url}: no ${EXTENSION} extension`);
    }
    if (!layout) return;
    const bin = header.binStart;
    if (!decoder && length >= bin + layout.recordStart) {
      decoder = new ProgressiveDecoder(layout, buffer.subarray(bin, length));
      fed = bin + layout.recordStart;
      onBase(decoder, layout, header.json);
    }
    if (decoder && length > fed) {
      decoder.push(buffer.subarray(fed, length));
      fed = length;
    }
  };
  const get = async (first, last = "") => {
    const response = await fetch(url, { headers: { Range: `bytes=${first}-${last}` } });
    if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
    return response;
  };
  let response = await get(0, kFirst - 1);
  if (response.status === 206) {
    total = Number(/\/(\d+)$/.exec(response.headers.get("Content-Range") ?? "")?.[1]) || 0;
    buffer = new Uint8Array(Math.max(total, kFirst));
    take(new Uint8Array(await response.arrayBuffer()));
    // The header's rest (a JSON past the first range), then the base's.
    while (!decoder && length < total) {
      const need = layout ? header.binStart + layout.recordStart : 2 * length;
      response = await get(length, Math.min(need, total) - 1);
      take(new Uint8Array(await response.arrayBuffer()));
    }
    response = !total || length < total ? await get(length) : null;
  } else {
    total = Number(response.headers.get("Content-Length")) || 0;
    buffer = new Uint8Array(Math.max(total, kFirst));
  }
  if (response) {
    const reader = response.body.getReader();
    for (;;) {
      const { done, value } = await reader.read();
      if (done) break;
      take(value);
    }
  }
  if (!decoder) throw new Error(`${url}: the file ends before its base mesh`);
  return decoder;
}

// three.js's GLTFLoader, given the whole file: the primitive's geometry grows into the whole
// mesh, `budgetMs` of records a call to gltf.userData.progressive.refine() (once a frame).
// Usage: loader.register((parser) => new VRSProgressivePlugin(parser, THREE)).
export class VRSProgressivePlugin {
  constructor(parser, THREE) {
    this.parser = parser;
    this.THREE = THREE;
    this.name = EXTENSION;
  }

  async afterRoot(gltf) {
    const json = this.parser.json;
    const layout = describeProgressive(json);
    if (!layout) return;
    const prim = json.meshes[0].primitives[0];
    const view = (i) => this.parser.getDependency("bufferView", i).then((b) => new Uint8Array(b));
    const indexAccessor = json.accessors[prim.indices];
    const [records, vertexBytes, indexBytes] = await Promise.all([
      view(prim.extensions[EXTENSION].bufferView),
      view(json.accessors[prim.attributes.POSITION].bufferView),
      view(indexAccessor.bufferView),
    ]);
    // The decoder reads the base from one binary chunk: the index view, then the vertex view.
    const binary = new Uint8Array(indexBytes.length + vertexBytes.length);
    binary.set(indexBytes, 0);
    binary.set(vertexBytes, indexBytes.length);
    const local = { ...layout, indexStart: indexAccessor.byteOffset ?? 0, vertexStart: indexBytes.length };
    const decoder = new ProgressiveDecoder(local, binary);
    decoder.push(records);
    let mesh = null;
    gltf.scene.traverse((o) => { if (!mesh && o.isMesh) mesh = o; });
    const geometry = growingGeometry(this.THREE, decoder, layout);
    if (mesh) {
      mesh.geometry.dispose();
      mesh.geometry = geometry;
    }
    gltf.userData.progressive = {
      decoder,
      refine: (budgetMs = 8, most = Infinity) =>
        refine(decoder, geometry, performance.now() + budgetMs, most),
    };
  }
}

// A BufferGeometry over the decoder's arrays (sized for the whole mesh), drawn up to its faces.
export function growingGeometry(THREE, decoder, layout) {
  const g = new THREE.BufferGeometry();
  const v = decoder.vertices;
  const floats = new THREE.InterleavedBuffer(new Float32Array(v.buffer, v.byteOffset, v.byteLength / 4), layout.stride / 4);
  const bytes = new THREE.InterleavedBuffer(v, layout.stride);
  floats.setUsage(THREE.DynamicDrawUsage);
  bytes.setUsage(THREE.DynamicDrawUsage);
  const names = { POSITION: "position", NORMAL: "normal", TEXCOORD_0: "uv", COLOR_0: "color" };
  for (const [k, a] of Object.entries(layout.attributes)) {
    const size = { VEC2: 2, VEC3: 3, VEC4: 4 }[a.type];
    if (a.componentType === 5126)
      g.setAttribute(names[k], new THREE.InterleavedBufferAttribute(floats, size, a.offset / 4));
    else g.setAttribute(names[k], new THREE.InterleavedBufferAttribute(bytes, size, a.offset, true));
  }
  const index = new THREE.BufferAttribute(decoder.indices, 1);
  index.setUsage(THREE.DynamicDrawUsage);
  g.setIndex(index);
  g.setDrawRange(0, decoder.faceCount * 3);
  g.boundingBox = new THREE.Box3(new THREE.Vector3(...layout.min), new THREE.Vector3(...layout.max));
  g.boundingSphere = g.boundingBox.getBoundingSphere(new THREE.Sphere());
  g.userData.floats = floats;
  g.userData.bytes = bytes;
  return g;
}

// Applies records until `deadline` (`most` of them at most) and hands the changed ranges to
// the GPU (added to those not uploaded yet; three.js clears them once it has); returns how many.
export function refine(decoder, geometry, deadline, most = Infinity) {
  decoder.resetChanges();
  const n = decoder.apply(deadline, most);
  if (!n) return 0;
  const stride = decoder.layout.stride;
  const { floats, bytes } = geometry.userData;
  const from = decoder.vertexFrom, to = decoder.vertexCount;
  if (to > from) {
    floats.addUpdateRange((from * stride) / 4, ((to - from) * stride) / 4);
    floats.needsUpdate = true;
    bytes.addUpdateRange(from * stride, (to - from) * stride);
    bytes.needsUpdate = true;
  }
  const index = geometry.index;
  index.addUpdateRange(decoder.indexLow, decoder.indexHigh - decoder.indexLow);
  index.needsUpdate = true;
  geometry.setDrawRange(0, decoder.faceCount * 3);
  return n;
}
