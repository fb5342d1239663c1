// afford serve's page: a WebSocket to the server (the messages are in
// serve/protocol.h), a three.js view of the scene it sends, and the
// controls that drive the hand when this page is the driver.
import * as THREE from '/three/build/three.module.js';
import { OrbitControls } from '/three/examples/jsm/controls/OrbitControls.js';
import { play } from './player.js';
import { pollGamepad } from './gamepad.js';

const $ = (id) => document.getElementById(id);
const view = $('view');
const viewing = new URLSearchParams(location.search).has('view');  // afford view: a recording, not a session

// What the browser test reads (tests/test_browser.cpp): frames drawn, and
// the time from a thumb command to the state that shows it (ms).
const measured = { frames: 0, latencies: [], pending: null };
window.affordPage = {
  measured,
  software: () => software,
  lastState: () => (state ? { t: state.t, frame: state.frame, deadline_misses: state.deadline_misses } : null),
  dragging: () => drag !== null,
  guides: () => ({ shown: guideGroups.fixed.visible, drawn: guideGroups.fixed.children.length + guideGroups.moving.children.length,
    legend: $('guides-legend').textContent, labels: guideLabels.map((l) => l.shown()) }),
  thumbOnScreen: () => (tips[0] ? toScreen(tips[0].position) : null),
  thumbClosingOnScreen: () => (tips[0] && state ? thumbClosingOnScreen() : null),
  toolOnScreen: () => (state ? toScreen(new THREE.Vector3().setFromMatrixPosition(new THREE.Matrix4().fromArray(state.object))) : null),
};

// ------------------------------------------------------------ the view

// WebGL drawn in software (SwiftShader: headless Chromium, a machine
// without a GPU) pays for every pixel on the CPU: there the page draws
// without antialiasing and at one pixel per CSS pixel (serve/README.md,
// "Speed").
function softwareGL() {
  const gl = document.createElement('canvas').getContext('webgl2') || document.createElement('canvas').getContext('webgl');
  if (!gl) return true;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|software/i.test(String(name));
}
const software = softwareGL();
const renderer = new THREE.WebGLRenderer({ antialias: !software });
renderer.setPixelRatio(software ? 1 : window.devicePixelRatio);
view.appendChild(renderer.domElement);
const scene3 = new THREE.Scene();
scene3.background = new THREE.Color(0x20242a);
const camera = new THREE.PerspectiveCamera(40, 1, 0.005, 20);
camera.up.set(0, 0, 1);  // the engine's world: z up
const controls = new OrbitControls(camera, renderer.domElement);
scene3.add(new THREE.HemisphereLight(0xffffff, 0x444444, 0.9));
const sun = new THREE.DirectionalLight(0xffffff, 0.7);
sun.position.set(0.5, -0.3, 1);
scene3.add(sun);
const grid = new THREE.GridHelper(1, 20, 0x555555, 0x333333);
grid.rotation.x = Math.PI / 2;  // in the z = 0 plane
scene3.add(grid);

function resize() {
  const w = view.clientWidth, h = view.clientHeight;
  renderer.setSize(w, h);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', resize);
new ResizeObserver(resize).observe(view);  // the layout settles after the first draw
resize();

// A group whose pose is set from a column-major 4x4 each state.
function posed() {
  const g = new THREE.Group();
  g.matrixAutoUpdate = false;
  scene3.add(g);
  return g;
}
const fixedArm = posed(), movingArm = posed(), acteeBody = posed();
let acteeMaterial = null, acteeColour = new THREE.Color(0xc08040);
const tips = [];
// The reaction the thumb feels (eq. 5), an arrow at the thumb pushing it
// open; 60 mm at the hand's largest force.
const reactionArrow = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 0.01, 0xff3030, 0.012, 0.008);
reactionArrow.visible = false;
scene3.add(reactionArrow);
let homeTarget = new THREE.Vector3(0.06, 0, 0.1), homeEye = new THREE.Vector3(0.35, -0.45, 0.4);

function meshOf(m, material) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(m.positions, 3));
  g.setAttribute('normal', new THREE.Float32BufferAttribute(m.normals, 3));
  return new THREE.Mesh(g, material);
}

function clear(group) {
  while (group.children.length) {
    const c = group.children.pop();
    if (c.geometry) c.geometry.dispose();
  }
}

function resetView() {
  camera.position.copy(homeEye);
  controls.target.copy(homeTarget);
  controls.update();
}

// The guides of `afford guide` (the scene's `guides`, serve/guides_message.h):
// each primitive hung on the arm whose frame it is in, so it follows the
// tool; the "guides" box shows or hides them.
const guideGroups = { fixed: new THREE.Group(), moving: new THREE.Group() };
function guideMaterial(c) {
  return new THREE.MeshBasicMaterial({ color: new THREE.Color(c[0], c[1], c[2]), transparent: true, opacity: c[3],
    side: THREE.DoubleSide, depthWrite: false });
}
function triangles(points, material) {  // a flat list of [x, y, z], three a triangle
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(points.flat(), 3));
  return new THREE.Mesh(g, material);
}
function buildGuides(g) {
  clear(guideGroups.fixed);
  clear(guideGroups.moving);
  fixedArm.add(guideGroups.fixed);
  movingArm.add(guideGroups.moving);
  const legend = $('guides-legend');
  legend.innerHTML = '';
  if (!g) return;
  const at = (c, u, su, v, sv) => [0, 1, 2].map((i) => c[i] + u[i] * su + v[i] * sv);
  for (const r of g.rects) {
    const [c, u, v, hu, hv] = [r.centre, r.u, r.v, r.half_u, r.half_v];
    const p = [at(c, u, -hu, v, -hv), at(c, u, hu, v, -hv), at(c, u, hu, v, hv), at(c, u, -hu, v, hv)];
    guideGroups[r.frame].add(triangles([p[0], p[1], p[2], p[0], p[2], p[3]], guideMaterial(r.colour)));
  }
  for (const m of g.meshes) {
    guideGroups[m.frame].add(triangles(m.triangles.flatMap((t) => t.map((i) => m.vertices[i])), guideMaterial(m.colour)));
  }
  for (const frame of ['fixed', 'moving']) {  // the advantage map: one coloured line per step along an arm
    const segments = g.segments.filter((s) => s.frame === frame);
    if (!segments.length) continue;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(segments.flatMap((s) => [...s.a, ...s.b]), 3));
    geometry.setAttribute('color', new THREE.Float32BufferAttribute(
      segments.flatMap((s) => [...s.colour.slice(0, 3), ...s.colour.slice(0, 3)]), 3));
    guideGroups[frame].add(new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ vertexColors: THREE.VertexColors })));
  }
  const mm = (m) => `${(m * 1000).toFixed(0)} mm`;
  const f = g.facts;
  const facts = {
    interaction_space: `from ${mm(f.interaction_space.from)} to ${mm(f.interaction_space.to)} along the arm`,
    emphasis: `push from ${mm(f.emphasis.from)} to ${mm(f.emphasis.to)} along the arms`,
    advantage: `mechanical advantage over the emphasis ${f.advantage.ma_min.toFixed(2)} to ${f.advantage.ma_max.toFixed(2)}`,
    symmetry_plane: `lever ${f.pattern}`,
  };
  for (const s of g.guides) {
    const d = document.createElement('div');
    d.className = 'guide';
    const c = s.colour.slice(0, 3).map((x) => Math.round(x * 255));
    d.innerHTML = `<span class="swatch" style="background: rgb(${c.join(',')})"></span> <b></b>: <span></span>`;
    d.children[1].textContent = s.name;
    d.children[2].textContent = `${s.description} ${facts[s.kind] ? `(${facts[s.kind]})` : ''}`;
    legend.appendChild(d);
  }
}
function showGuides(on) {
  guideGroups.fixed.visible = guideGroups.moving.visible = on;
  $('labels').hidden = !on;
}

// The guides' labels (symmetry plane, interaction space, push, force
// amplification, load): HTML over the view, each at the screen image of
// its anchor on its arm, moved at each frame (a transform: no layout).
const guideLabels = [];
function buildLabels(g) {
  const layer = $('labels');
  layer.innerHTML = '';
  guideLabels.length = 0;
  for (const l of g ? g.labels : []) {
    const el = document.createElement('span');
    el.textContent = l.text;
    const c = l.colour.slice(0, 3).map((x) => Math.round(x * 255));
    el.style.color = el.style.borderColor = `rgb(${Math.max(...c) < 90 ? c.map((x) => x + 120).join(',') : c.join(',')})`;
    layer.appendChild(el);
    const anchor = new THREE.Vector3(...l.anchor), at = new THREE.Vector3();
    const arm = l.frame === 'moving' ? movingArm : fixedArm;
    let x = 0, y = 0, visible = false, shown = '';
    guideLabels.push({
      place(width, height) {
        at.copy(anchor).applyMatrix4(arm.matrix).project(camera);
        visible = at.z > -1 && at.z < 1 && Math.abs(at.x) <= 1 && Math.abs(at.y) <= 1;
        x = (at.x + 1) / 2 * width;
        y = (1 - at.y) / 2 * height;
        // Written only when it moves a pixel: an unchanged label is not painted again.
        const style = visible ? `translate(${Math.round(x)}px, ${Math.round(y)}px)` : 'none';
        if (style === shown) return;
        shown = style;
        el.style.display = visible ? '' : 'none';
        if (visible) el.style.transform = style;
      },
      shown: () => ({ text: l.text, guide: g.guides[l.guide].kind, x, y, visible: visible && !layer.hidden }),
    });
  }
}
function placeLabels() {
  if ($('labels').hidden || guideLabels.length === 0) return;
  camera.updateMatrixWorld();
  const w = renderer.domElement.clientWidth, h = renderer.domElement.clientHeight;
  for (const l of guideLabels) l.place(w, h);
}

let scene = null;  // the last scene message
function buildScene(s) {
  scene = s;
  clear(guideGroups.fixed);
  clear(guideGroups.moving);
  clear(fixedArm);
  clear(movingArm);
  clear(acteeBody);
  const metal = new THREE.MeshLambertMaterial({ color: 0x9aa4ad });  // without an environment map, more metal draws darker
  for (const p of s.parts) {
    const mesh = meshOf(p, metal);
    mesh.matrixAutoUpdate = false;
    mesh.matrix.fromArray(p.in_arm);
    (p.arm === 'moving' ? movingArm : fixedArm).add(mesh);
  }
  if (s.actee) {
    acteeColour = new THREE.Color(s.actee.colour);
    acteeMaterial = new THREE.MeshLambertMaterial({ color: acteeColour });
    acteeBody.add(meshOf(s.actee, acteeMaterial));
  }
  buildGuides(s.guides);
  buildLabels(s.guides);
  for (const t of tips) scene3.remove(t);
  tips.length = 0;
  s.fingertip_radius.forEach((r, i) => {
    const m = new THREE.Mesh(new THREE.SphereGeometry(r, 20, 14),
      new THREE.MeshLambertMaterial({ color: i === 0 ? 0xff8c1a : 0xe0b090 }));
    m.userData.finger = i;
    scene3.add(m);
    tips.push(m);
  });
  const h = s.hand_start;
  homeTarget = new THREE.Vector3(h[0] * 0.7, h[1] * 0.5, h[2] * 0.5);
  homeEye = homeTarget.clone().add(new THREE.Vector3(0.25, -0.45, 0.3));
  resetView();
  $('trial').textContent = `session ${s.session}, trial ${s.trial} (participant ${s.participant}), ` +
    `actee ${s.actee_name || 'none'}; recording ${s.recording}`;
  $('events').innerHTML = '';
  $('log').innerHTML = '';
  const shelf = $('shelf');
  shelf.innerHTML = '';
  for (const name of s.shelf) {
    const b = document.createElement('button');
    b.textContent = name;
    b.className = 'driver';
    b.onclick = () => send({ type: 'actee', name });
    shelf.appendChild(b);
  }
  setRole(role);
}

// Text is set only when it changes: an unchanged panel is not laid out
// or painted again.
const shownText = new Map();
function setText(id, text) {
  if (shownText.get(id) === text) return;
  shownText.set(id, text);
  $(id).textContent = text;
}
let readout = '', readoutAt = -Infinity, readoutTimer = null;
function showReadout() {
  readoutTimer = null;
  readoutAt = performance.now();
  setText('readout', readout);
}

let state = null;  // the last state message
function applyState(st) {
  state = st;
  fixedArm.matrix.fromArray(st.object);
  movingArm.matrix.fromArray(st.moving_arm);
  acteeBody.matrix.fromArray(st.actee);
  st.fingertips.forEach((p, i) => { if (tips[i]) tips[i].position.set(p[0], p[1], p[2]); });
  if (acteeMaterial) acteeMaterial.color.set(st.condition === 'broken' ? 0xffee88 : acteeColour);
  bar('reaction-bar', st.reaction, st.max_force);
  drawReaction(st);
  bar('actee-bar', st.actee_load, st.actee_limit);
  setText('reaction', `${st.reaction.toFixed(1)} N of ${st.max_force.toFixed(0)} N`);
  setText('actee-load', st.actee_limit > 0
    ? `${st.actee_load.toFixed(1)} N of its limit ${st.actee_limit.toFixed(0)} N (${st.condition})` : 'none');
  // The readout's time changes every state: written 10 times a second
  // (each change lays out and paints the panel again, in software).
  readout = `t ${st.t.toFixed(2)} s, angle ${(st.angle * 180 / Math.PI).toFixed(1)} deg, ` +
    `squeeze ${(st.squeeze * 1000).toFixed(1)} mm (asked ${(st.squeeze_target * 1000).toFixed(1)} mm), ` +
    `${st.grasped ? 'grasped' : st.gripping ? 'closing' : 'open'}${st.held ? ', held' : ''}; ` +
    `late frames ${st.deadline_misses}`;
  const wait = readoutAt + 100 - performance.now();
  if (wait <= 0) showReadout();
  else if (!readoutTimer) readoutTimer = setTimeout(showReadout, wait);  // the last state shows too
  plot(st);
  const p = measured.pending;
  if (p && st.applied_seq >= p.seq) {
    measured.latencies.push(performance.now() - p.at);
    measured.pending = null;
  }
}

function drawReaction(st) {
  const f = st.max_force > 0 ? st.reaction / st.max_force : 0;
  reactionArrow.visible = f > 0.01 && tips[0] !== undefined;
  if (!reactionArrow.visible) return;
  const o = new THREE.Matrix4().fromArray(st.object);
  const origin = new THREE.Vector3().setFromMatrixPosition(o);
  const axis = new THREE.Vector3(0, 0, 1).transformDirection(o);
  const thumb = tips[0].position;
  const opening = axis.cross(thumb.clone().sub(origin)).normalize();  // +theta
  reactionArrow.position.copy(thumb);
  reactionArrow.setDirection(opening);
  reactionArrow.setLength(0.06 * Math.min(1, f) + 0.015, 0.012, 0.008);
}

// A strip chart of the last 10 s of session time: the thumb's reaction and
// the actee's load (against the larger of the hand's force and the limit),
// and the angle (against the tool's range). A point every 1/30 s, drawn
// when one is added, on a canvas kept in memory (willReadFrequently: not
// through the software GL a headless browser has).
const history = [];
const timeline = $('timeline').getContext('2d', { willReadFrequently: true });
function plot(st) {
  if (history.length && st.t < history[history.length - 1].t) history.length = 0;  // a new trial
  if (history.length && st.t - history[history.length - 1].t < 1 / 30) return;
  history.push({ t: st.t, reaction: st.reaction, load: st.actee_load, angle: st.angle });
  while (history.length && history[0].t < st.t - 10) history.shift();
  const c = timeline.canvas, g = timeline;
  g.clearRect(0, 0, c.width, c.height);
  const top = Math.max(st.max_force, st.actee_limit, 1);
  const x = (t) => (t - (st.t - 10)) / 10 * c.width;
  const line = (colour, y) => {
    g.strokeStyle = colour;
    g.beginPath();
    history.forEach((h, i) => (i ? g.lineTo : g.moveTo).call(g, x(h.t), c.height * (1 - Math.max(0, Math.min(1, y(h))))));
    g.stroke();
  };
  const lo = scene.theta.min, hi = scene.theta.max;
  line('#999', (h) => (h.angle - lo) / Math.max(1e-9, hi - lo));
  line('#3a7', (h) => h.reaction / top);
  line('#c60', (h) => h.load / top);
}

function bar(id, value, limit) {
  const f = limit > 0 ? value / limit : 0;
  const width = `${(Math.max(0, Math.min(1, f)) * 100).toFixed(1)}%`;
  if (shownText.get(id) === width) return;  // unchanged: not laid out again
  shownText.set(id, width);
  const el = $(id);
  el.firstElementChild.style.width = width;
  el.classList.toggle('over', f >= 1);
}

function addEvent(e) {
  if (e.kind === 'inferred') {
    const li = document.createElement('li');
    li.innerHTML = `<span class="fn"></span> at ${e.t.toFixed(3)} s`;
    li.firstChild.textContent = e.function;
    for (const n of e.explanation || []) {
      const d = document.createElement('div');
      d.className = 'why';
      d.textContent = `${n.t.toFixed(3)} s  ${n.text}` + (n.detail ? ` (${n.detail})` : '');
      li.appendChild(d);
    }
    $('events').appendChild(li);
    return li;
  } else {
    const d = document.createElement('div');
    d.textContent = `${e.t.toFixed(3)} s ${e.function}: ${e.kind === 'node_reached' ? 'reached' : 'lost'} ${e.text}`;
    const log = $('log');
    log.appendChild(d);
    while (log.childNodes.length > 50) log.removeChild(log.firstChild);
    log.scrollTop = log.scrollHeight;
  }
  return null;
}

// ------------------------------------------------------------ the socket

let socket = null, seq = 0, role = 'watcher', latestState = null;
function send(message) {
  if (!socket || socket.readyState !== WebSocket.OPEN || role !== 'driver') return;
  socket.send(JSON.stringify({ ...message, seq: ++seq }));
  if (message.type === 'thumb' && !measured.pending) measured.pending = { seq, at: performance.now() };
}

function setRole(r) {
  role = r;
  for (const b of document.querySelectorAll('aside button, button.driver')) {
    if (b.id !== 'view-reset') b.disabled = r !== 'driver';
  }
  $('status').textContent = viewing ? 'viewing a recording' : r === 'driver' ? 'driving' : 'watching (another page drives)';
}

function connect() {
  socket = new WebSocket(`ws://${location.host}/ws`);
  socket.onmessage = (ev) => {
    let m;
    try { m = JSON.parse(ev.data); } catch { return; }
    if (m.type === 'hello' || m.type === 'role') setRole(m.role);
    else if (m.type === 'scene') buildScene(m);
    else if (m.type === 'state' && scene) latestState = m;  // drawn at the next frame: a slow page skips states, never lags
    else if (m.type === 'event') addEvent(m);
    else if (m.type === 'error') $('error').textContent = m.message;
  };
  socket.onclose = () => {
    $('status').textContent = 'disconnected: retrying...';
    setTimeout(connect, 1000);
  };
}
if (viewing) {
  document.body.classList.add('viewing');
  play({ buildScene, applyState, addEvent }).catch((e) => { $('error').textContent = `cannot play the recording: ${e}`; });
} else {
  connect();
}

// ------------------------------------------------------------ the controls

const squeezeStep = 0.002;  // m per key press
function squeezeTo(target) {
  if (!scene || !state) return;
  const s = Math.max(0, Math.min(scene.limits.max_squeeze, target));
  send({ type: 'thumb', squeeze: s });
}
function moveHand(dx, dy, dz) {
  if (!scene || !state) return;
  const h = state.hand;  // column-major: translation at 12, 13, 14
  const lo = scene.limits.hand_min, hi = scene.limits.hand_max;
  const p = [h[12] + dx, h[13] + dy, h[14] + dz].map((v, i) => Math.max(lo[i], Math.min(hi[i], v)));
  send({ type: 'move', position: p });
}

$('grasp').onclick = () => send({ type: 'grasp' });
$('release').onclick = () => send({ type: 'release' });
$('reset').onclick = () => send({ type: 'reset' });
$('view-reset').onclick = resetView;
$('guides-on').onchange = (e) => showGuides(e.target.checked);

window.addEventListener('keydown', (e) => {
  const k = e.key;
  const target = state ? state.squeeze_target : 0;
  if (k === 'ArrowUp') squeezeTo(target + squeezeStep);
  else if (k === 'ArrowDown') squeezeTo(target - squeezeStep);
  else if (k === 'g') send({ type: 'grasp' });
  else if (k === 'r') send({ type: 'release' });
  else if (k === 'v') resetView();
  else if (k === 'w') moveHand(0, 0.01, 0);
  else if (k === 's') moveHand(0, -0.01, 0);
  else if (k === 'a') moveHand(-0.01, 0, 0);
  else if (k === 'd') moveHand(0.01, 0, 0);
  else if (k === 'q') moveHand(0, 0, 0.01);
  else if (k === 'e') moveHand(0, 0, -0.01);
  else return;
  e.preventDefault();
});

// Dragging the thumb: the pointer's motion projected on the screen image
// of the thumb's closing direction (the tangent of its arc about the
// pivot, eq. 1) sets the squeeze.
const raycaster = new THREE.Raycaster();
let drag = null;
function toScreen(p) {  // page pixels (CSS), on the canvas as it is laid out now
  const v = p.clone().project(camera);
  const r = renderer.domElement.getBoundingClientRect();
  return new THREE.Vector2(r.left + (v.x + 1) / 2 * r.width, r.top + (1 - v.y) / 2 * r.height);
}

// The screen image of the thumb's closing direction: a unit vector (view
// pixels) and pixels per metre of squeeze; null when it is edge-on.
function thumbClosingOnScreen() {
  const o = new THREE.Matrix4().fromArray(state.object);
  const origin = new THREE.Vector3().setFromMatrixPosition(o);
  const axis = new THREE.Vector3(0, 0, 1).transformDirection(o);
  const thumb = tips[0].position.clone();
  const closing = axis.clone().cross(thumb.clone().sub(origin)).negate().normalize();  // -theta
  const a = toScreen(thumb), b = toScreen(thumb.clone().addScaledVector(closing, 0.01));
  const dir = b.clone().sub(a);
  const pixelsPerMetre = dir.length() / 0.01;
  return pixelsPerMetre < 1 ? null : { dir: dir.normalize(), pixelsPerMetre };
}
renderer.domElement.addEventListener('pointerdown', (e) => {
  if (!state || !tips[0] || role !== 'driver') return;
  const r = renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2((e.clientX - r.left) / r.width * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
  raycaster.setFromCamera(ndc, camera);
  if (raycaster.intersectObject(tips[0]).length === 0) return;
  const along = thumbClosingOnScreen();
  if (!along) return;
  const { dir, pixelsPerMetre } = along;
  drag = { x: e.clientX, y: e.clientY, dir: dir.normalize(), pixelsPerMetre, start: state.squeeze_target };
  controls.enabled = false;
  renderer.domElement.setPointerCapture(e.pointerId);
});
renderer.domElement.addEventListener('pointermove', (e) => {
  if (!drag) return;
  const along = (e.clientX - drag.x) * drag.dir.x + (e.clientY - drag.y) * drag.dir.y;
  squeezeTo(drag.start + along / drag.pixelsPerMetre);
});
const endDrag = () => { drag = null; controls.enabled = true; };
renderer.domElement.addEventListener('pointerup', endDrag);
renderer.domElement.addEventListener('pointercancel', endDrag);

function frame() {
  measured.frames++;
  if (latestState) {
    applyState(latestState);
    latestState = null;
  }
  if (!viewing && role === 'driver' && scene && state) pollGamepad(state, scene.limits.max_squeeze, send);
  controls.update();
  placeLabels();
  renderer.render(scene3, camera);
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);
