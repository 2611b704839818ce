// The page: a three.js scene that draws each level as lod_stream.js delivers it, the numbers
// beside it, a wireframe toggle, file drop. `?url=F.glb` opens F; `&reference=K` draws level K
// as three.js's own GLTFLoader reads the whole file instead (the browser tests compare both).
// State for tests: window.viewer.{levels, done, error, bytes, total}.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { MeshoptDecoder } from "three/addons/libs/meshopt_decoder.module.js";
import { RangeSource, streamLevels } from "./lod_stream.js";

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
(function loop() {
  requestAnimationFrame(loop);
  controls.update();
  renderer.render(scene, camera);
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
  if (params.has("reference")) reference(absolute, Number(params.get("reference"))).catch(fail);
  else {
    const stop = params.has("stop") ? Number(params.get("stop")) : undefined; // tests: stop at level K
    open(absolute, absolute, url.split("/").pop(), stop).catch(fail);
  }
}
