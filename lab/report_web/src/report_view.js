// The interactive 3D views of sketchlab's report.html. Each recording's
// `.scene-row` holds one `.scene` per stack (data-scene: the case's
// scene.gltf, relative to the report). The glTF itself comes from
// `<case>/scene.gltf.js` (window.sketchlabScenes[path]), a classic script:
// browsers refuse fetch() and ES modules from file://, and the report must
// open from a local folder. One WebGL canvas per row (browsers cap WebGL
// contexts at ~16), each stack in its own viewport, all drawn with one
// camera: the views are linked by construction.
//
// For the browser test (tests/lab/report_web_test.sh), the page records on
// <body>: data-scene-views = views drawn, data-scene-nonblank = views with
// pixels other than the background, data-scene-errors = errors seen.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

const errors = [];
const note = (message) => {
  errors.push(String(message));
  document.body.dataset.sceneErrors = errors.join(' | ');
};
window.addEventListener('error', (e) => note(e.message));
window.addEventListener('unhandledrejection', (e) => note(e.reason));

function parseGltf(json) {
  return new Promise((resolve, reject) => {
    new GLTFLoader().parse(JSON.stringify(json), '', resolve, reject);
  });
}

// Lines and points as VTK drew them: points as fixed-size dots, lines flat.
function styleScene(root) {
  root.traverse((o) => {
    if (o.isPoints) {
      o.material = new THREE.PointsMaterial({ color: o.material.color, size: 6, sizeAttenuation: false });
    } else if (o.isLine) {
      o.material = new THREE.LineBasicMaterial({
        color: o.material.color, vertexColors: !!o.geometry.attributes.color });
    } else if (o.isMesh) {
      o.material.side = THREE.DoubleSide;
      if (o.material.opacity < 1) { o.material.transparent = true; o.material.depthWrite = false; }
    }
  });
}

async function setupRow(row) {
  const views = [...row.querySelectorAll('.scene')];
  const scenes = [];
  for (const view of views) {
    const key = view.dataset.scene;
    const json = (window.sketchlabScenes || {})[key];
    const title = document.createElement('div');
    title.className = 'title';
    title.textContent = view.dataset.title || key;
    view.appendChild(title);
    if (!json) { note('no scene data for ' + key); scenes.push(null); continue; }
    try {
      const gltf = await parseGltf(json);
      const scene = new THREE.Scene();
      scene.background = new THREE.Color(0xffffff);
      scene.add(new THREE.HemisphereLight(0xffffff, 0x888888, 2.0));
      const sun = new THREE.DirectionalLight(0xffffff, 1.5);
      sun.position.set(1, 2, 3);
      scene.add(sun);
      styleScene(gltf.scene);
      scene.add(gltf.scene);
      scenes.push(scene);
    } catch (e) {
      note(key + ': ' + (e && e.message ? e.message : e));
      scenes.push(null);
    }
  }
  // One camera framing every stack's scene.
  const box = new THREE.Box3();
  for (const s of scenes) if (s) box.expandByObject(s);
  if (box.isEmpty()) return;
  const centre = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-6);
  const camera = new THREE.PerspectiveCamera(30, 1, radius / 100, radius * 100);
  const dir = new THREE.Vector3(1, 0.8, 1.2).normalize();
  camera.position.copy(centre).addScaledVector(dir, radius / Math.sin((15 * Math.PI) / 180));
  camera.lookAt(centre);

  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setScissorTest(true);
  const canvas = renderer.domElement;
  canvas.style.cssText = 'position:absolute;left:0;top:0;width:100%;height:100%;z-index:0';
  row.style.position = 'relative';
  row.appendChild(canvas);
  const controls = new OrbitControls(camera, canvas);
  controls.target.copy(centre);

  const draw = () => {
    const rowRect = row.getBoundingClientRect();
    renderer.setSize(rowRect.width, rowRect.height, false);
    views.forEach((view, i) => {
      const r = view.getBoundingClientRect();
      const x = r.left - rowRect.left, y = rowRect.bottom - r.bottom;
      renderer.setViewport(x, y, r.width, r.height);
      renderer.setScissor(x, y, r.width, r.height);
      camera.aspect = r.width / Math.max(r.height, 1);
      camera.updateProjectionMatrix();
      if (scenes[i]) renderer.render(scenes[i], camera);
    });
  };
  controls.addEventListener('change', draw);
  window.addEventListener('resize', draw);
  controls.update();
  draw();
  return countNonBlank(renderer, row, views, scenes);
}

// Views with at least a few pixels that are not the white background.
function countNonBlank(renderer, row, views, scenes) {
  const gl = renderer.getContext();
  const rowRect = row.getBoundingClientRect();
  const ratio = renderer.getPixelRatio();
  let drawn = 0, nonblank = 0;
  views.forEach((view, i) => {
    if (!scenes[i]) return;
    drawn++;
    const r = view.getBoundingClientRect();
    const w = Math.max(1, Math.floor(r.width * ratio)), h = Math.max(1, Math.floor(r.height * ratio));
    const x = Math.floor((r.left - rowRect.left) * ratio), y = Math.floor((rowRect.bottom - r.bottom) * ratio);
    const px = new Uint8Array(w * h * 4);
    gl.readPixels(x, y, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    let n = 0;
    for (let k = 0; k < px.length; k += 4) if (px[k] < 240 || px[k + 1] < 240 || px[k + 2] < 240) n++;
    if (n >= 10) nonblank++;
  });
  return { drawn, nonblank };
}

async function main() {
  let drawn = 0, nonblank = 0;
  for (const row of document.querySelectorAll('.scene-row')) {
    try {
      const r = await setupRow(row);
      if (r) { drawn += r.drawn; nonblank += r.nonblank; }
    } catch (e) {
      note(e && e.message ? e.message : e);
    }
  }
  document.body.dataset.sceneViews = String(drawn);
  document.body.dataset.sceneNonblank = String(nonblank);
  document.body.dataset.sceneDone = '1';
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', main);
else main();
