// The page: a three.js scene that draws each level as lod_stream.js delivers it, the numbers
// beside it, a wireframe toggle, file drop. `?url=F.glb` opens F; `&reference=K` draws level K
// as three.js's own GLTFLoader reads the whole file instead (the browser tests compare both).
// A progressive .glb (docs/progressive.md) is drawn from its base, then refined record by
// record as its bytes arrive, within a budget a frame; `&stop=N` stops after N records, and
// `&reference=N` draws the file as GLTFLoader reads it with the VRS_mesh_progressive plugin,
// N records applied.
// State for tests: window.viewer.{levels, done, error, bytes, total, progressive}.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { MeshoptDecoder } from "three/addons/libs/meshopt_decoder.module.js";
import { RangeSource, streamLevels } from "./lod_stream.js";
import { EXTENSION, VRSProgressivePlugin, growingGeometry, refine, streamProgressive }
  from "./progressive.js";

const $ = (id) => document.getElementById(id);
const state = (window.viewer = { levels: [], done: false, error: null, bytes: 0, total: 0,
                                  textureReady: true, textureError: null });

const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
$("view").appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x20242a);
const camera = new THREE.PerspectiveCamera(35, 1, 0.01, 1000);
scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.8);
sun.position.set(1, 2, 3);
camera.add(sun);
scene.add(camera);
const controls = new OrbitControls(camera, renderer.domElement);
let current = null; // the mesh drawn
let material = null;
let wireframe = false;

function resize() {
  renderer.setSize(window.innerWidth, window.innerHeight);
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
}
window.addEventListener("resize", resize);
resize();
let refining = null; // a progressive file's per-frame step
(function loop() {
  requestAnimationFrame(loop);
  const t = performance.now();
  refining?.();
  controls.update();
  renderer.render(scene, camera);
  if (refining && state.progressive) { // the first frames compile the shaders: not refining
    const p = state.progressive;
    if (++p.frames > 2) p.longestFrameMs = Math.max(p.longestFrameMs, performance.now() - t);
  }
})();

// Frames the box [min, max] from a fixed direction (the same for every level and for the
// reference: screenshots compare).
function frame(min, max) {
  const c = new THREE.Vector3().fromArray(min).add(new THREE.Vector3().fromArray(max)).multiplyScalar(0.5);
  const r = new THREE.Vector3().fromArray(max).sub(new THREE.Vector3().fromArray(min)).length() / 2 || 1;
  const d = r / Math.sin((camera.fov * Math.PI) / 360);
  camera.position.copy(c).add(new THREE.Vector3(0.35, 0.3, 1).normalize().multiplyScalar(d * 1.05));
  camera.near = d / 100;
  camera.far = d * 10;
  camera.updateProjectionMatrix();
  controls.target.copy(c);
  controls.update();
}

function makeMaterial(layout, baseUrl, hasNormals, hasColors) {
  const m = new THREE.MeshStandardMaterial({
    color: 0xffffff, metalness: 0, roughness: 1, vertexColors: hasColors, flatShading: !hasNormals,
  });
  if (layout.image) {
    const url = new URL(layout.image, baseUrl).href;
    state.textureReady = false;
    new THREE.TextureLoader().load(url, (t) => {
      t.flipY = false; // glTF's texture coordinates start at the image's top left
      t.wrapS = t.wrapT = THREE.RepeatWrapping; // glTF's default sampler
      t.colorSpace = THREE.SRGBColorSpace;
      m.map = t;
      m.needsUpdate = true;
      state.textureReady = true;
    }, undefined, () => { // a missing image: drawn without, and said
      state.textureError = url;
      state.textureReady = true;
      $("hint").textContent = `texture not found: ${url}`;
    });
  }
  return m;
}

// A level's geometry over the vertex prefix: one interleaved buffer seen as floats (position,
// normal, texture coordinates) and as bytes (colors).
function geometryOf(vertices, indices, layout) {
  const g = new THREE.BufferGeometry();
  // A view of the stream's one vertex buffer: finer levels only write past this prefix.
  const floats = new THREE.InterleavedBuffer(
    new Float32Array(vertices.buffer, vertices.byteOffset, vertices.byteLength / 4), layout.stride / 4);
  const bytes = new THREE.InterleavedBuffer(vertices, layout.stride);
  const attrs = layout.levels[0].attributes;
  const names = { POSITION: "position", NORMAL: "normal", TEXCOORD_0: "uv", COLOR_0: "color" };
  for (const [k, a] of Object.entries(attrs)) {
    const size = { VEC2: 2, VEC3: 3, VEC4: 4 }[a.type];
    if (a.componentType === 5126)
      g.setAttribute(names[k], new THREE.InterleavedBufferAttribute(floats, size, a.offset / 4));
    else g.setAttribute(names[k], new THREE.InterleavedBufferAttribute(bytes, size, a.offset, true));
  }
  g.setIndex(new THREE.BufferAttribute(indices, 1));
  return g;
}

function show(object) {
  if (current) {
    scene.remove(current);
    current.geometry?.dispose();
  }
  current = object;
  scene.add(object);
}

function table(layout, drawn) {
  const rows = layout.levels.map((l, k) => {
    const e = l.extras.error !== undefined ? `error ≤ ${Number(l.extras.error).toPrecision(3)}` : "";
    const cls = k === drawn ? ' class="drawn"' : "";
    return `<tr><td${cls}>level ${k}</td><td>${(100 * (l.extras.ratio ?? 1)).toPrecision(3)} %</td>` +
      `<td>${l.faces.toLocaleString()} faces</td><td>${e}</td></tr>`;
  });
  $("levels").innerHTML = rows.join("");
}

async function open(source, baseUrl, title, stopAfter) {
  state.levels = [];
  state.done = false;
  state.error = null;
  $("title").textContent = title;
  const t0 = performance.now();
  const reader = new RangeSource(source, (n) => {
    state.bytes = n;
    $("bytes").textContent = n.toLocaleString();
  });
  let framed = false;
  await streamLevels(reader, async ({ level, index, vertices, indices, layout }) => {
    state.total = layout.total;
    $("total").textContent = layout.total.toLocaleString();
    const attrs = layout.levels[0].attributes;
    if (!material) material = makeMaterial(layout, baseUrl, !!attrs.NORMAL, !!attrs.COLOR_0);
    material.wireframe = wireframe;
    if (!framed) {
      const p = layout.levels[0].attributes.POSITION;
      frame(p.min, p.max);
      framed = true;
    }
    show(new THREE.Mesh(geometryOf(vertices, indices, layout), material));
    table(layout, index);
    $("level").textContent = `level ${index} of ${layout.levels.length - 1}, ` +
      `${level.faces.toLocaleString()} faces`;
    renderer.render(scene, camera);
    state.levels.push({ index, faces: level.faces, vertices: level.vertices, bytes: reader.received,
                        ms: performance.now() - t0 });
  }, { stopAfter, decoder: MeshoptDecoder });
  state.done = true;
}

// Level K as three.js's GLTFLoader reads the whole file: the reference the tests compare with.
async function reference(url, k) {
  const gltf = await new GLTFLoader().setMeshoptDecoder(MeshoptDecoder).loadAsync(url);
  const json = gltf.parser.json;
  const top = json.scenes[json.scene ?? 0].nodes[0];
  const nodeIds = [top, ...(json.nodes[top].extensions?.MSFT_lod?.ids ?? [])];
  const mesh = await gltf.parser.getDependency("mesh", json.nodes[nodeIds[k]].mesh);
  const src = mesh.isMesh ? mesh : mesh.children[0];
  const p = json.accessors[json.meshes[json.nodes[nodeIds[0]].mesh].primitives[0].attributes.POSITION];
  frame(p.min, p.max);
  const attrs = json.meshes[0].primitives[0].attributes;
  material = makeMaterial({ image: json.images?.[0]?.uri }, url, !!attrs.NORMAL, !!attrs.COLOR_0);
  show(new THREE.Mesh(src.geometry, material));
  renderer.render(scene, camera);
  state.levels.push({ index: k, faces: src.geometry.index.count / 3 });
  state.done = true;
}

// A progressive file: the base as soon as its bytes are in, then records as they arrive, a
// budget of milliseconds a frame; `stop`: no more than that many records.
async function openProgressive(url, title, stop) {
  $("title").textContent = title;
  const p = (state.progressive = { baseBytes: 0, baseMs: 0, applied: 0, insertions: 0,
                                   faces: 0, vertices: 0, frames: 0, longestFrameMs: 0, longestRefineMs: 0,
                                   samples: [] });
  const t0 = performance.now();
  let decoder = null, geometry = null;
  const budgetMs = 8;
  const update = () => {
    p.applied = decoder.applied;
    p.faces = decoder.faceCount;
    p.vertices = decoder.vertexCount;
    $("level").textContent = `${p.faces.toLocaleString()} faces, ${p.vertices.toLocaleString()} ` +
      `vertices (${p.applied.toLocaleString()} of ${p.insertions.toLocaleString()} records)`;
  };
  await streamProgressive(url, {
    onBase: (d, layout) => {
      decoder = d;
      p.insertions = layout.insertions;
      p.baseBytes = state.bytes;
      p.baseMs = performance.now() - t0;
      const attrs = layout.attributes;
      material = makeMaterial(layout, url, !!attrs.NORMAL, !!attrs.COLOR_0);
      material.wireframe = wireframe;
      frame(layout.min, layout.max);
      geometry = growingGeometry(THREE, d, layout);
      show(new THREE.Mesh(geometry, material));
      update();
      state.levels.push({ index: 0, faces: d.faceCount, bytes: p.baseBytes, ms: p.baseMs });
      refining = () => {
        const limit = stop ?? Infinity;
        if (decoder.applied >= limit) return;
        const before = decoder.applied;
        const t = performance.now();
        refine(decoder, geometry, t + budgetMs, limit - decoder.applied);
        p.longestRefineMs = Math.max(p.longestRefineMs, performance.now() - t);
        if (decoder.applied > before) {
          update();
          p.samples.push([Math.round(performance.now() - t0), state.bytes, decoder.applied]);
        }
      };
    },
    onBytes: (n, total) => {
      state.bytes = n;
      state.total = total;
      $("bytes").textContent = n.toLocaleString();
      $("total").textContent = total.toLocaleString();
    },
  });
  // Every byte in: done once every record (or `stop` of them) is applied and drawn.
  await new Promise((resolve) => {
    const wait = () => decoder.applied >= Math.min(stop ?? Infinity, decoder.layout.insertions)
      ? resolve() : requestAnimationFrame(wait);
    wait();
  });
  await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
  p.doneMs = performance.now() - t0;
  state.done = true;
}

// The file as GLTFLoader reads it, with the plugin: its first `count` records applied.
async function referenceProgressive(url, count) {
  const loader = new GLTFLoader().register((parser) => new VRSProgressivePlugin(parser, THREE));
  const gltf = await loader.loadAsync(url);
  const progressive = gltf.userData.progressive;
  while (progressive.decoder.applied < count) {
    const room = count - progressive.decoder.applied;
    if (!progressive.refine(Infinity, room)) break;
  }
  let mesh = null;
  gltf.scene.traverse((o) => { if (!mesh && o.isMesh) mesh = o; });
  const layout = progressive.decoder.layout;
  frame(layout.min, layout.max);
  material = makeMaterial(layout, url, !!layout.attributes.NORMAL, !!layout.attributes.COLOR_0);
  show(new THREE.Mesh(mesh.geometry, material));
  renderer.render(scene, camera);
  state.progressive = { applied: progressive.decoder.applied, faces: progressive.decoder.faceCount };
  state.done = true;
}

// Whether the file at `url` is a progressive one (its JSON, read by a range request).
async function isProgressive(url) {
  const source = new RangeSource(url);
  const head = new DataView(await source.read(0, 20));
  const json = JSON.parse(new TextDecoder().decode(await source.read(20, 20 + head.getUint32(12, true))));
  return !!json.meshes?.[0]?.primitives?.[0]?.extensions?.[EXTENSION];
}

function fail(e) {
  state.error = String(e?.message ?? e);
  $("level").textContent = `error: ${state.error}`;
}

$("wireframe").addEventListener("change", (e) => {
  wireframe = e.target.checked;
  if (material) material.wireframe = wireframe;
});
$("file").addEventListener("change", (e) => {
  const f = e.target.files[0];
  if (f) open(f, window.location.href, f.name).catch(fail);
});
window.addEventListener("dragover", (e) => {
  e.preventDefault();
  $("drop").style.display = "flex";
});
window.addEventListener("dragleave", () => ($("drop").style.display = "none"));
window.addEventListener("drop", (e) => {
  e.preventDefault();
  $("drop").style.display = "none";
  const f = e.dataTransfer.files[0];
  if (f) open(f, window.location.href, f.name).catch(fail);
});

const params = new URLSearchParams(window.location.search);
const url = params.get("url");
if (url) {
  const absolute = new URL(url, window.location.href).href;
  const stop = params.has("stop") ? Number(params.get("stop")) : undefined; // tests: level K, or K records
  isProgressive(absolute).then((progressive) => {
    if (progressive && params.has("reference"))
      return referenceProgressive(absolute, Number(params.get("reference")));
    if (progressive) return openProgressive(absolute, url.split("/").pop(), stop);
    if (params.has("reference")) return reference(absolute, Number(params.get("reference")));
    return open(absolute, absolute, url.split("/").pop(), stop);
  }).catch(fail);
}
