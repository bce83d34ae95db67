// The previewer's page: a Tick 1 scene in 3D, what the tick's camera sees, and the ray-traced image.
//
// Coordinates. The tick is LEFT-handed: x right, y up, z into the screen (handout, Figure 2), and
// its camera sits at the origin looking along +z. three.js is right-handed, with its cameras
// looking along -z. Negating z maps one onto the other: a point (x, y, z) of the scene file is
// drawn at (x, y, -z), which keeps x right and y up, puts +z in front of a default three.js
// camera at the origin, and turns the tick's camera into exactly such a camera.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { CSS2DObject, CSS2DRenderer } from 'three/addons/renderers/CSS2DRenderer.js';

/** A point or direction of the scene file, in three.js's coordinates. */
function toThree([x, y, z]) {
  return new THREE.Vector3(x, y, -z);
}

// The tick's camera (spec, "Camera and image"): 45 degrees across, and the CLI's 640 x 480 frame.
const HORIZONTAL_FOV = 45 * Math.PI / 180;
const ASPECT = 640 / 480;
const HALF_WIDTH = Math.tan(HORIZONTAL_FOV / 2);   // of the image plane at z = 1
const HALF_HEIGHT = HALF_WIDTH / ASPECT;
// three.js's cameras take the vertical field of view, in degrees.
const VERTICAL_FOV_DEGREES = 2 * Math.atan(HALF_HEIGHT) * 180 / Math.PI;

const VIEW_BACKGROUND = 0x555555;       // the course previewer's grey
const TICK_BACKGROUND = 0x191919;       // the ray tracer's background, 0.1 grey truncated to 25
const CAMERA_LAYER = 1;                 // what the tick's camera sees: the spheres only

// Flat colours are the file's own #RRGGBB digits, shown as they are: no colour management,
// no tone mapping, so the inset's pixels can be checked against the file.
THREE.ColorManagement.enabled = false;

function makeRenderer(options) {
  // preserveDrawingBuffer keeps the last frame readable (tests read it); logarithmic depth keeps
  // spheres apart from near the camera out to the loader's 1e9 limit.
  const renderer = new THREE.WebGLRenderer({ preserveDrawingBuffer: true, logarithmicDepthBuffer: true, ...options });
  renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
  renderer.setPixelRatio(1);
  return renderer;
}

const scene = new THREE.Scene();
let content = new THREE.Group();    // everything that depends on the loaded scene
scene.add(content);

const viewRenderer = makeRenderer({ antialias: true });
viewRenderer.setClearColor(VIEW_BACKGROUND);
document.getElementById('view').appendChild(viewRenderer.domElement);
// The axes' names are HTML, laid over the 3D view (below the bar and the panels) at their arrows' tips.
const labelRenderer = new CSS2DRenderer();
labelRenderer.domElement.id = 'axis-labels';
Object.assign(labelRenderer.domElement.style, { position: 'fixed', top: '0', left: '0', pointerEvents: 'none' });
document.getElementById('view').after(labelRenderer.domElement);
const orbitCamera = new THREE.PerspectiveCamera(50, 1, 0.01, 1e6);
const controls = new OrbitControls(orbitCamera, viewRenderer.domElement);
controls.addEventListener('change', draw);

const insetCanvas = document.getElementById('camera-view');
const insetRenderer = makeRenderer({ canvas: insetCanvas, antialias: false });
insetRenderer.setClearColor(TICK_BACKGROUND);
insetRenderer.setSize(insetCanvas.width, insetCanvas.height, false);
const tickCamera = new THREE.PerspectiveCamera(VERTICAL_FOV_DEGREES, ASPECT, 1e-3, 1e10);
tickCamera.layers.set(CAMERA_LAYER);   // at the origin, looking along three's -z: the tick's +z

// The bar covers the top of the view, and the panels (with any warnings or error beside or above
// them) its bottom: the orbit camera's centre of projection is moved into the band left free
// between them, and a scene is framed to fit that band, so that neither hides a sphere or the light.
const bar = document.getElementById('bar');
const panels = document.getElementById('panels');
const message = document.getElementById('message');
let freeFraction = 1;   // the share of the view's height between the bar and the panels

function resize() {
  const width = window.innerWidth, height = window.innerHeight;
  viewRenderer.setSize(width, height);
  labelRenderer.setSize(width, height);
  const lowest = message.hidden ? panels : [panels, message].reduce((a, b) => (top(a) < top(b) ? a : b));
  // Together they may take at most 60% of the height: a tiny window still shows the scene.
  const scale = Math.min(1, 0.6 * height / (bar.offsetHeight + height - top(lowest) + 12));
  const above = bar.offsetHeight * scale, below = (height - top(lowest) + 12) * scale;
  freeFraction = (height - above - below) / height;
  orbitCamera.aspect = width / height;
  orbitCamera.setViewOffset(width, height, 0, (below - above) / 2, width, height);
  orbitCamera.updateProjectionMatrix();
  draw();
}

function top(element) {
  return element.getBoundingClientRect().top;
}
window.addEventListener('resize', resize);

function draw() {
  viewRenderer.render(scene, orbitCamera);
  labelRenderer.render(scene, orbitCamera);
  insetRenderer.render(scene, tickCamera);
}

// ---------------------------------------------------------------------------------------------
// Building the 3D view from the server's description of a scene (all in the tick's coordinates).

function build(description) {
  scene.remove(content);
  content.traverse(object => {
    object.geometry?.dispose();
    object.material?.map?.dispose();
    object.material?.dispose();
  });
  content = new THREE.Group();
  scene.add(content);

  const spheres = description ? description.spheres : [];
  const light = description ? description.light : null;
  // The ground grid lies under everything: at y = -1, or a whole unit below the lowest sphere.
  const lowest = Math.min(-1, ...spheres.map(s => s.position[1] - s.radius));
  const groundY = Math.floor(lowest);
  const reach = Math.max(5, ...spheres.map(s => Math.max(Math.abs(s.position[0]), Math.abs(s.position[2])) + s.radius),
    ...(light ? [Math.abs(light.position[0]), Math.abs(light.position[2])] : []));

  content.add(grid(groundY, reach));
  content.add(viewLights(light));
  content.add(cameraPyramid());
  for (const sphere of spheres) {
    content.add(sphereMesh(sphere));
  }
  if (light) {
    content.add(lightIcon(light, groundY));
  }
  frame(spheres, light);
  draw();
}

/**
 * A sphere twice over: shaded for the 3D view, so that its depth reads at a glance, and flat for
 * the camera view, which shows where each sphere lies in the tick's image, not how it is lit.
 */
function sphereMesh({ position, radius, colour }) {
  const group = new THREE.Group();
  const geometry = new THREE.SphereGeometry(radius, 64, 32);
  const shaded = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({ color: colour }));
  const flat = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({ color: colour }));
  flat.layers.set(CAMERA_LAYER);
  group.add(shaded, flat);
  group.position.copy(toThree(position));
  return group;
}

/**
 * The 3D view's lighting: a white light where the scene's point light is (above and behind the
 * camera without one), with no fall-off, and a soft ambient light so that no side is black.
 */
function viewLights(light) {
  const group = new THREE.Group();
  group.add(new THREE.AmbientLight(0xffffff, 0.9));
  const lamp = new THREE.PointLight(0xffffff, 2.2, 0, 0);
  lamp.position.copy(toThree(light ? light.position : [-2, 4, -2]));
  group.add(lamp);
  return group;
}

/** A square grid of unit cells (coarser for big scenes) centred under the origin, well beyond the scene. */
function grid(groundY, reach) {
  const half = Math.max(10, Math.ceil(reach * 2));
  const divisions = Math.min(200, 2 * half);
  const helper = new THREE.GridHelper(2 * half, divisions, 0xaaaaaa, 0x8a8a8a);
  helper.position.y = groundY;
  return helper;
}

/**
 * Arrows along the tick's +x (red), +y (green) and +z (blue), from the origin, each named at its
 * tip. They are the same for every scene, so they are made once, outside {@code content}.
 */
function axes() {
  const group = new THREE.Group();
  const arrows = [['x', 'right', [1, 0, 0], 0xff2020], ['y', 'up', [0, 1, 0], 0x20e020],
    ['z', 'into the screen', [0, 0, 1], 0x2040ff]];
  for (const [name, meaning, direction, colour] of arrows) {
    group.add(new THREE.ArrowHelper(toThree(direction), new THREE.Vector3(), 1.2, colour, 0.2, 0.08));
    const element = document.createElement('div');
    element.className = 'axis-label';
    element.dataset.axis = name;
    element.textContent = name;
    element.title = `${name}: ${meaning}`;
    // The arrow's colour, lightened to be read on the grey view.
    element.style.color = '#' + new THREE.Color(colour).lerp(new THREE.Color(0xffffff), 0.4).getHexString();
    const label = new CSS2DObject(element);
    label.position.copy(toThree(direction).multiplyScalar(1.4));
    group.add(label);
  }
  return group;
}
scene.add(axes());

/** The camera: apex at the origin, base the image plane at z = 1 (45 degrees across, 4:3). */
function cameraPyramid() {
  const corners = [[-1, 1], [1, 1], [1, -1], [-1, -1]].map(([sx, sy]) => toThree([sx * HALF_WIDTH, sy * HALF_HEIGHT, 1]));
  const origin = new THREE.Vector3();
  const points = [];
  corners.forEach((corner, i) => {
    points.push(origin, corner);                                  // an edge from the apex
    points.push(corner, corners[(i + 1) % corners.length]);      // a side of the base
  });
  const geometry = new THREE.BufferGeometry().setFromPoints(points);
  return new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: 0xffffff }));
}

/** The point light: a sun in the light's colour, always the same size on screen, with a dashed line to the grid. */
function lightIcon({ position, colour }, groundY) {
  const group = new THREE.Group();
  const at = toThree(position);
  const sun = new THREE.Sprite(new THREE.SpriteMaterial({ map: sunTexture(colour), sizeAttenuation: false, depthTest: false }));
  sun.scale.set(0.07, 0.07, 1);
  sun.position.copy(at);
  sun.renderOrder = 1;
  group.add(sun);
  const drop = new THREE.Line(new THREE.BufferGeometry().setFromPoints([at, new THREE.Vector3(at.x, groundY, at.z)]),
    new THREE.LineDashedMaterial({ color: colour, dashSize: 0.1, gapSize: 0.08 }));
  drop.computeLineDistances();
  group.add(drop);
  return group;
}

function sunTexture(colour) {
  const size = 128;
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = size;
  const g = canvas.getContext('2d');
  g.translate(size / 2, size / 2);
  g.fillStyle = g.strokeStyle = colour;
  g.beginPath();
  g.arc(0, 0, size * 0.2, 0, 2 * Math.PI);
  g.fill();
  g.lineWidth = size * 0.07;
  g.lineCap = 'round';
  for (let i = 0; i < 8; i++) {
    const angle = i * Math.PI / 4;
    g.beginPath();
    g.moveTo(Math.cos(angle) * size * 0.3, Math.sin(angle) * size * 0.3);
    g.lineTo(Math.cos(angle) * size * 0.44, Math.sin(angle) * size * 0.44);
    g.stroke();
  }
  return new THREE.CanvasTexture(canvas);
}

/** Points the orbit camera at the scene from behind, above and to the left of the tick's camera, as the course's previewer does. */
function frame(spheres, light) {
  // At least the camera and the space just in front of it, where the tick's scenes usually are.
  const box = new THREE.Box3().setFromPoints([toThree([-1, -1, 0]), toThree([1, 1, 5])]);
  for (const s of spheres) {
    box.union(new THREE.Box3().setFromCenterAndSize(toThree(s.position), new THREE.Vector3().setScalar(2 * s.radius)));
  }
  if (light) {
    box.expandByPoint(toThree(light.position));
  }
  const bounds = box.getBoundingSphere(new THREE.Sphere());
  const vertical = orbitCamera.fov * freeFraction;
  const horizontal = 2 * THREE.MathUtils.radToDeg(Math.atan(Math.tan(THREE.MathUtils.degToRad(orbitCamera.fov / 2)) * orbitCamera.aspect));
  const fitsIn = Math.min(vertical, horizontal);
  // Close enough that the bounding sphere's outline just fits: the scene itself, smaller than
  // its bounding sphere, then fills most of the free part of the view.
  const distance = 0.9 * bounds.radius / Math.tan(THREE.MathUtils.degToRad(fitsIn / 2));
  const direction = toThree([-1.2, 1.0, -1.5]).normalize();
  orbitCamera.position.copy(bounds.center).addScaledVector(direction, distance);
  orbitCamera.near = distance / 1000;
  orbitCamera.far = distance * 100;
  orbitCamera.updateProjectionMatrix();
  controls.target.copy(bounds.center);
  controls.update();
}

// ---------------------------------------------------------------------------------------------
// Loading scenes: the one named on the command line at start, then whatever is dropped or picked.
// The server parses and renders them with the CLI's own loader and renderer.

const body = document.body;
const nameLine = document.getElementById('scene-name');
const raytraced = document.getElementById('raytraced');
const raytracedLink = document.getElementById('raytraced-link');
const raytracedCaption = document.getElementById('raytraced-caption');
let generation = 0;   // a later load supersedes any earlier one still in flight
let inFlight = null;  // the AbortController of that earlier load: aborting it stops its render on the server

function showMessage(kind, lines) {
  message.hidden = lines.length === 0;
  message.className = kind;
  message.textContent = lines.join('\n');
  resize();   // the box may reach above the panels, and then the band a scene is framed in is smaller
}

function showImage(blob, name) {
  if (raytraced.src) {
    URL.revokeObjectURL(raytraced.src);
  }
  if (!blob) {
    raytraced.removeAttribute('src');
    raytracedLink.removeAttribute('href');
    raytracedCaption.textContent = 'Ray traced by tick1';
    return;
  }
  raytracedCaption.textContent = 'Ray traced by tick1 (click to save)';
  const url = URL.createObjectURL(blob);
  raytraced.onload = () => {
    body.dataset.rendered = name;
    body.dataset.status = 'shown';
  };
  raytraced.src = url;
  raytracedLink.href = url;
  raytracedLink.download = name.replace(/^.*[\\/]/, '').replace(/\.xml$/i, '') + '.png';
}

/** A PNG sent as base64 (the render's answer is JSON: see PreviewServer), as a Blob to show. */
function pngBlob(base64) {
  const bytes = Uint8Array.from(atob(base64), c => c.charCodeAt(0));
  return new Blob([bytes], { type: 'image/png' });
}

/**
 * Shows one scene: {@code request(path, signal)} fetches /api/scene or /api/render for it (GET
 * for the command line's scene, POST of the file for a dropped one).
 */
async function load(name, request) {
  const mine = ++generation;
  if (inFlight) inFlight.abort();
  const controller = new AbortController();
  inFlight = controller;
  body.dataset.status = 'loading';
  delete body.dataset.rendered;
  nameLine.textContent = name;
  try {
    const response = await request('/api/scene', controller.signal);
    const description = await response.json();
    if (mine !== generation) return;
    if (!response.ok) {
      // 404: no scene was named on the command line; anything else: the loader's message.
      const noScene = response.status === 404;
      build(null);
      showImage(null);
      showMessage('error', noScene ? [] : [description.error]);
      body.dataset.status = noScene ? 'empty' : 'error';
      return;
    }
    nameLine.textContent = description.name;
    showMessage('warning', description.warnings);   // first: the scene is framed clear of the warnings
    build(description);
    body.dataset.status = 'rendering';
    raytracedCaption.textContent = 'Ray tracing...';
    const render = await request('/api/render', controller.signal);
    // The answer may begin with spaces, sent while the server renders; JSON allows them.
    const result = await render.json();
    if (mine !== generation) return;
    if (!render.ok || result.error) {
      showImage(null);
      showMessage('error', [result.error]);
      body.dataset.status = 'error';
      return;
    }
    showImage(pngBlob(result.png), description.name);
  } catch (error) {
    if (mine !== generation || error.name === 'AbortError') return;
    showMessage('error', ['The previewer did not answer (is tick1 preview still running?): ' + error.message]);
    body.dataset.status = 'error';
  }
}

function loadFile(file) {
  // The File goes as the request body as it is: the browser streams it, and the server applies
  // the loader's size limit.
  const query = '?name=' + encodeURIComponent(file.name);
  load(file.name, (path, signal) => fetch(path + query,
    { method: 'POST', body: file, headers: { 'Content-Type': 'application/xml' }, signal }));
}

document.getElementById('file').addEventListener('change', event => {
  const file = event.target.files[0];
  event.target.value = '';   // picking the same file again reloads it
  if (file) loadFile(file);
});

// Drag and drop anywhere on the page.
let dragDepth = 0;
window.addEventListener('dragenter', event => { event.preventDefault(); dragDepth++; body.classList.add('dragging'); });
window.addEventListener('dragleave', () => { if (--dragDepth <= 0) { dragDepth = 0; body.classList.remove('dragging'); } });
window.addEventListener('dragover', event => event.preventDefault());
window.addEventListener('drop', event => {
  event.preventDefault();
  dragDepth = 0;
  body.classList.remove('dragging');
  const file = event.dataTransfer.files[0];
  if (file) loadFile(file);
});

resize();
build(null);
load('', (path, signal) => fetch(path, { signal }));
