// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stripe editor's page: draws the mesh with three.js, shades the stripes per pixel from the
// per-corner coordinate u that the server sends (cos u, so stripes stay crisp at any frequency;
// on a cross field the brighter of cos u and cos v, a grid), draws every branch face of a line or
// cross field as the three triangles around its branch point that the server sends, and turns
// clicks and drags into edits (POST /api/edit). On a cross field, the quad preview draws the edges
// of the quad mesh of its lines that the server extracts after every edit. With ?selftest=1 it runs the browser
// test's script: real pointer events on the canvas, checks, frames sent to the server.
'use strict';

const canvas = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio || 1);
renderer.setClearColor(0xf4f4f0);
const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
const controls = new THREE.OrbitControls(camera, canvas);
controls.enableDamping = false;
controls.addEventListener('change', () => requestRender());

// The server answers only requests that carry the token of the address it printed (?token=...).
const token = new URLSearchParams(window.location.search).get('token') || '';
function api(path, options = {}) {
  return fetch(path, Object.assign({}, options, { headers: Object.assign({ 'X-Editor-Token': token }, options.headers || {}) }));
}
// the answer of a GET, or the server's message as an error (a missing token, say)
async function apiGet(path) {
  const response = await api(path);
  if (!response.ok) {
    let message = `HTTP ${response.status}`;
    try { message = (await response.json()).error || message; } catch (e) { /* not JSON */ }
    throw new Error(message);
  }
  return response;
}

const ui = {
  mesh: document.getElementById('mesh'), field: document.getElementById('field'),
  stripes: document.getElementById('stripes'), stripesValue: document.getElementById('stripes-value'),
  error: document.getElementById('error'), hint: document.getElementById('hint'),
  singularities: document.getElementById('singularities'), latency: document.getElementById('latency'),
  selftest: document.getElementById('selftest'), family: document.getElementById('family-choice'),
  automatic: document.getElementById('automatic'), quads: document.getElementById('quads'),
  quadStatus: document.getElementById('quad-status'), exportQuads: document.getElementById('export-quads')
};
// the stripe family that clicks add to (a cross field's first or second family)
function family() {
  const checked = document.querySelector('input[name="family"]:checked');
  return state && state.families > 1 && checked ? Number(checked.value) : 0;
}

// ---------------------------------------------------------------- the picture

const vertexShader = `
attribute float u;
attribute float v;
attribute float mark;
varying float vU;
varying float vV;
varying float vMark;
varying vec3 vNormal;
void main() {
  vU = u;
  vV = v;
  vMark = mark;
  vNormal = normalize(normalMatrix * normal);
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}`;
const fragmentShader = `
uniform float families;
varying float vU;
varying float vV;
varying float vMark;
varying vec3 vNormal;
void main() {
  if (vMark > 2.5) discard; // a branch face: the overlay's three triangles draw it
  // cos u per pixel, its 0.5 level set antialiased over one pixel: crisp stripes at any frequency
  float c = families > 1.5 ? max(cos(vU), cos(vV)) : cos(vU);
  float t = 0.5 + 0.5 * c;
  float w = max(fwidth(t), 1e-4);
  float band = smoothstep(0.5 - w, 0.5 + w, t);
  vec3 base = mix(vec3(0.16, 0.18, 0.22), vec3(0.97, 0.95, 0.88), band);
  if (vMark > 1.5) base = mix(base, vec3(0.18, 0.65, 0.25), 0.75);       // field singularity
  else if (vMark > 0.5) base = mix(base, vec3(0.85, 0.15, 0.15), 0.75);  // +k
  else if (vMark < -0.5) base = mix(base, vec3(0.15, 0.35, 0.85), 0.75); // -k
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;
  float light = 0.35 + 0.65 * max(dot(n, normalize(vec3(0.3, 0.5, 1.0))), 0.0);
  gl_FragColor = vec4(base * light, 1.0);
}`;
const material = new THREE.ShaderMaterial({ vertexShader, fragmentShader, side: THREE.DoubleSide,
  uniforms: { families: { value: 1 } } });
material.extensions.derivatives = true;
// the surface a little behind its depth, so that the quad preview's lines on it stay visible
material.polygonOffset = true;
material.polygonOffsetFactor = 1;
material.polygonOffsetUnits = 1;

let model = null;   // { mesh json, object, geometry, centroids, faceNormals }
let overlay = null; // the branch faces' triangles of the last state (a THREE.Mesh)
let quadLines = null; // the quad preview's edges of the last state (a THREE.LineSegments)
let state = null;   // the last state from the server
let dirty = false;
const markers = new THREE.Group();
scene.add(markers);

function requestRender() {
  if (dirty) return;
  dirty = true;
  requestAnimationFrame(() => { dirty = false; render(); });
}
function render() {
  const w = canvas.clientWidth, h = canvas.clientHeight;
  if (canvas.width !== Math.floor(w * renderer.getPixelRatio()) || canvas.height !== Math.floor(h * renderer.getPixelRatio())) {
    renderer.setSize(w, h, false);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
  }
  renderer.render(scene, camera);
}
window.addEventListener('resize', requestRender);

function buildModel(json) {
  if (model) { scene.remove(model.object); model.geometry.dispose(); }
  const nf = json.faces, P = json.positions, T = json.triangles;
  const position = new Float32Array(9 * nf), normal = new Float32Array(9 * nf);
  const vertexNormal = new Float32Array(P.length);
  const centroids = new Float32Array(3 * nf);
  for (let f = 0; f < nf; ++f) {
    const a = 3 * T[3 * f], b = 3 * T[3 * f + 1], c = 3 * T[3 * f + 2];
    const e1 = [P[b] - P[a], P[b + 1] - P[a + 1], P[b + 2] - P[a + 2]];
    const e2 = [P[c] - P[a], P[c + 1] - P[a + 1], P[c + 2] - P[a + 2]];
    const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    for (const v of [a, b, c]) for (let i = 0; i < 3; ++i) vertexNormal[v + i] += n[i]; // area-weighted
    for (let i = 0; i < 3; ++i) centroids[3 * f + i] = (P[a + i] + P[b + i] + P[c + i]) / 3;
  }
  for (let f = 0; f < nf; ++f)
    for (let k = 0; k < 3; ++k) {
      const v = 3 * T[3 * f + k];
      const len = Math.hypot(vertexNormal[v], vertexNormal[v + 1], vertexNormal[v + 2]) || 1;
      for (let i = 0; i < 3; ++i) {
        position[9 * f + 3 * k + i] = P[v + i];
        normal[9 * f + 3 * k + i] = vertexNormal[v + i] / len;
      }
    }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(position, 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(normal, 3));
  geometry.setAttribute('u', new THREE.BufferAttribute(new Float32Array(3 * nf), 1));
  geometry.setAttribute('v', new THREE.BufferAttribute(new Float32Array(3 * nf), 1));
  geometry.setAttribute('mark', new THREE.BufferAttribute(new Float32Array(3 * nf), 1));
  geometry.computeBoundingSphere();
  const object = new THREE.Mesh(geometry, material);
  scene.add(object);
  const boundary = new Set(json.boundary_faces);
  model = { json, object, geometry, centroids, boundary };
  // frame the mesh
  const s = geometry.boundingSphere;
  controls.target.copy(s.center);
  camera.near = s.radius / 100;
  camera.far = s.radius * 100;
  camera.position.copy(s.center).add(new THREE.Vector3(0, 0, 3.2 * s.radius));
  camera.updateProjectionMatrix();
  controls.update();
  // the frequency slider: logarithmic from 1 stripe to the most the mesh resolves
  ui.stripes.dataset.max = json.max_stripes;
}

function centroid(f) {
  const c = model.centroids;
  return new THREE.Vector3(c[3 * f], c[3 * f + 1], c[3 * f + 2]);
}

// The triangles around the branch points: 15 floats each, x y z u v at its three corners.
function buildOverlay(data) {
  if (overlay) { scene.remove(overlay); overlay.geometry.dispose(); overlay = null; }
  const count = data.length / 15;
  if (!count) return;
  const position = new Float32Array(9 * count), normal = new Float32Array(9 * count);
  const u = new Float32Array(3 * count), v = new Float32Array(3 * count);
  for (let t = 0; t < count; ++t) {
    const p = [0, 1, 2].map((k) => new THREE.Vector3(data[15 * t + 5 * k], data[15 * t + 5 * k + 1], data[15 * t + 5 * k + 2]));
    const n = new THREE.Vector3().subVectors(p[1], p[0]).cross(new THREE.Vector3().subVectors(p[2], p[0])).normalize();
    for (let k = 0; k < 3; ++k) {
      p[k].toArray(position, 9 * t + 3 * k);
      n.toArray(normal, 9 * t + 3 * k);
      u[3 * t + k] = data[15 * t + 5 * k + 3];
      v[3 * t + k] = data[15 * t + 5 * k + 4];
    }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(position, 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(normal, 3));
  geometry.setAttribute('u', new THREE.BufferAttribute(u, 1));
  geometry.setAttribute('v', new THREE.BufferAttribute(v, 1));
  geometry.setAttribute('mark', new THREE.BufferAttribute(new Float32Array(3 * count), 1));
  overlay = new THREE.Mesh(geometry, material);
  scene.add(overlay);
}

// The quad preview's edges are straight chords between points on the surface: drawn a little
// nearer the camera (a depth bias of about a hundredth of the mesh's size at the default view),
// so that the curved surface does not hide them, while the far side still does.
const quadLineMaterial = new THREE.ShaderMaterial({
  vertexShader: `void main() {
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
  gl_Position.z -= 2e-5 * gl_Position.w;
}`,
  fragmentShader: 'void main() { gl_FragColor = vec4(0.72, 0.11, 0.11, 1.0); }'
});
// The quad preview's edges: 6 floats each, x y z at its two ends; drawn over the surface.
function buildQuadLines(data) {
  if (quadLines) { scene.remove(quadLines); quadLines.geometry.dispose(); quadLines = null; }
  if (!data.length) return;
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(data), 3));
  quadLines = new THREE.LineSegments(geometry, quadLineMaterial);
  scene.add(quadLines);
}

function applyState(buffer) {
  const view = new DataView(buffer);
  const length = view.getUint32(0, true);
  const json = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 4, length)));
  const data = new Float32Array(buffer, 4 + length);
  const nf = model ? model.json.faces : -1;
  const stripeData = 3 * nf * json.families + 15 * json.overlay;
  if (!model || data.length !== stripeData + 6 * json.quad_edges) throw new Error('the state does not fit the mesh');
  state = json;
  model.geometry.attributes.u.array.set(data.subarray(0, 3 * nf));
  model.geometry.attributes.u.needsUpdate = true;
  if (json.families === 2) {
    model.geometry.attributes.v.array.set(data.subarray(3 * nf, 6 * nf));
    model.geometry.attributes.v.needsUpdate = true;
  }
  material.uniforms.families.value = json.families;
  buildOverlay(data.subarray(3 * nf * json.families, stripeData));
  buildQuadLines(data.subarray(stripeData));
  const mark = model.geometry.attributes.mark.array;
  mark.fill(0);
  while (markers.children.length) {
    const ball = markers.children[0];
    markers.remove(ball);
    ball.geometry.dispose();
    ball.material.dispose();
  }
  const radius = 0.012 * model.json.diagonal;
  const put = (f, value, color, scale = 1) => {
    for (let k = 0; k < 3; ++k) mark[3 * f + k] = value;
    const ball = new THREE.Mesh(new THREE.SphereBufferGeometry(scale * radius, 12, 8), new THREE.MeshBasicMaterial({ color }));
    ball.position.copy(centroid(f));
    ball.userData.face = f;
    markers.add(ball);
  };
  // the field's singularities: editable ones (a trivial connection's) green, the others teal;
  // a branch face (mark 3) is drawn by the overlay's three triangles instead of the face
  const editable = new Set(state.field_singularities.map(([f]) => f));
  for (const [f] of state.branch_faces) {
    for (let k = 0; k < 3; ++k) mark[3 * f + k] = 3;
    if (!editable.has(f)) put(f, 3, 0x80cbc4, 0.6);
  }
  const branch = new Set(state.branch_faces.map(([f]) => f));
  for (const [f] of state.field_singularities) put(f, branch.has(f) ? 3 : 2, 0x2e7d32);
  for (const [f, k] of state.singularities) put(f, k > 0 ? 1 : -1, k > 0 ? 0xc62828 : 0x1565c0);
  model.geometry.attributes.mark.needsUpdate = true;
  showState();
}

// k / n as text: +1, -1/2, +1/4
function fraction(k, n) {
  const g = (a, b) => (b ? g(b, a % b) : a);
  const d = g(Math.abs(k), n);
  return `${k > 0 ? '+' : '-'}${Math.abs(k) / d}${n / d > 1 ? '/' + n / d : ''}`;
}
function showState() {
  const lines = state.singularities.map(([f, k, a]) => `<span class="${k > 0 ? 'plus' : 'minus'}">face ${f}: ${k > 0 ? '+' : ''}${k}${state.families > 1 ? ` (family ${a + 1})` : ''}</span>`);
  const editable = new Set(state.field_singularities.map(([f]) => f));
  for (const [f, k] of state.field_singularities) lines.push(`<span class="field">field: face ${f}: ${fraction(k, state.order)}</span>`);
  for (const [f, k] of state.branch_faces) if (!editable.has(f)) lines.push(`<span class="field">field (fixed): face ${f}: ${fraction(k, state.order)}</span>`);
  ui.singularities.innerHTML = lines.length ? lines.join('\n') : 'none';
  ui.stripesValue.textContent = state.stripes.toFixed(1);
  // the field menu shows the server's field (after a refused change, or another mesh)
  const f = state.field;
  const value = f.kind === 'axis' ? `axis:${f.axis.map((x) => Math.round(x * 1e6) / 1e6).join(',')}`
    : f.kind === 'heat' ? `heat:${Math.round(f.degrees)}` : f.kind + (f.order > 1 && f.kind !== 'principal' ? `@${f.order}` : '') +
      (f.cones ? `+${f.cones}` : '') + (f.boundary ? `+${f.boundary}` : '');
  ui.family.hidden = state.families < 2;
  ui.automatic.disabled = state.order < 2;
  ui.quads.disabled = state.order !== 4;
  ui.quads.checked = state.quads.on;
  ui.exportQuads.disabled = !(state.quads.on && state.quads.valid);
  ui.quadStatus.textContent = !state.quads.on ? (state.order === 4 ? 'off' : 'off (a cross field only)')
    : state.quads.valid ? `${state.quads.faces} quads, ${state.quads.irregular_vertices} irregular vertices (the cones)` +
      (state.quads.boundary_loops ? `, ${state.quads.boundary_loops} boundary loops followed` : '') +
      (state.quads.stiffening_rounds ? `, ${state.quads.stiffening_rounds} rounds of stiffening` : '')
    : `not a quad mesh: ${state.quads.problem}`;
  if ([...ui.field.options].some((o) => o.value === value)) ui.field.value = value;
  const max = Number(ui.stripes.dataset.max);
  ui.stripes.value = String(Math.round(1000 * Math.log(Math.max(state.stripes, 1)) / Math.log(Math.max(max, 1.0001))));
  const closed = model.json.closed_components_euler.length > 0;
  ui.hint.textContent = `${model.json.name}: ${model.json.vertices} vertices, ${model.json.faces} faces` +
    (closed ? '. Closed: stripe indices sum to 0, add them in pairs.' : '.');
}

// ---------------------------------------------------------------- talking to the server

let latencyLog = [];
function showLatency(label, t0, json) {
  const t = json.timing || {};
  const frame = performance.now() - t0;
  latencyLog.push({ label, frame_ms: frame, server_ms: t.server_ms, solve_ms: t.solve_ms });
  ui.latency.textContent =
    `${label}\nevent to picture  ${frame.toFixed(1)} ms\nserver            ${(t.server_ms || 0).toFixed(1)} ms` +
    `\n  solve           ${(t.solve_ms || 0).toFixed(1)} ms` +
    (t.field_ms !== undefined ? `\n  field           ${t.field_ms.toFixed(1)} ms` : '') +
    (t.quads_ms !== undefined ? `\n  quads           ${t.quads_ms.toFixed(1)} ms` : '') +
    `\n  serialize       ${(t.serialize_ms || 0).toFixed(2)} ms`;
}

function showError(message) { ui.error.textContent = message; }

// Edits go one at a time, in order. While one is in flight, a new move that continues the last
// queued move (its "from" is that move's "to") is merged into it, and a new frequency replaces
// the queued one: a fast drag costs one re-solve per answer, not one per mouse event.
const queue = [];
let busy = false;
let acceptedEdits = 0; // edits the server applied (the browser test compares with its version)
function mergeable(last, request) {
  if (last.request.op !== request.op) return false;
  if (request.op === 'frequency') { last.request = request; return true; }
  if ((request.op === 'move' || request.op === 'move_field_singularity') && last.request.to === request.from) {
    last.request.to = request.to;
    return true;
  }
  return false;
}
function edit(request, t0 = performance.now(), label = request.op) {
  return new Promise((resolve) => {
    const last = queue[queue.length - 1];
    if (last && mergeable(last, request)) { last.waiters.push(resolve); return; }
    queue.push({ request, t0, label, waiters: [resolve] });
    if (!busy) pump();
  });
}
async function pump() {
  busy = true;
  while (queue.length) {
    const item = queue.shift();
    const ok = await send(item);
    if (!ok && item.request.op.startsWith('move')) {
      // the singularity stayed where the refused move started: later moves of the drag start there
      for (let i = queue.length - 1; i >= 0; --i)
        if (queue[i].request.op === item.request.op) queue.splice(i, 1)[0].waiters.forEach((w) => w(false));
      if (drag) drag.from = item.request.from;
    }
    item.waiters.forEach((w) => w(ok));
  }
  busy = false;
}
async function send({ request, t0, label }) {
  try {
    const response = await api('api/edit', { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(request) });
    if (!response.ok) {
      let message = `HTTP ${response.status}`;
      try { message = (await response.json()).error || message; } catch (e) { /* not JSON */ }
      showError(message);
      return false;
    }
    const buffer = await response.arrayBuffer();
    if (request.op !== 'state' && request.op !== 'load') ++acceptedEdits;
    if (request.op === 'load') {
      acceptedEdits = 0; // a new session on the server: its version starts again
      await loadMesh();
    }
    applyState(buffer);
    showError('');
    render();
    await new Promise((resolve) => requestAnimationFrame(resolve));
    showLatency(label, t0, state);
    return true;
  } catch (e) {
    showError(`the server did not answer (${e.message}); is surface_design_editor still running?`);
    return false;
  }
}

async function loadMesh() {
  const json = await (await apiGet('api/mesh')).json();
  buildModel(json);
}

async function start() {
  const meshes = await (await apiGet('api/meshes')).json();
  ui.mesh.innerHTML = '';
  for (const name of meshes.meshes) {
    const option = document.createElement('option');
    option.value = option.textContent = name;
    ui.mesh.appendChild(option);
  }
  ui.mesh.value = meshes.current;
  await loadMesh();
  applyState(await (await apiGet('api/state')).arrayBuffer());
  render();
}

// ---------------------------------------------------------------- interaction

const raycaster = new THREE.Raycaster();
function pick(clientX, clientY) {
  if (!model) return null;
  const r = canvas.getBoundingClientRect();
  const ndc = new THREE.Vector2(((clientX - r.left) / r.width) * 2 - 1, -((clientY - r.top) / r.height) * 2 + 1);
  raycaster.setFromCamera(ndc, camera);
  const hits = raycaster.intersectObject(model.object);
  return hits.length ? { face: hits[0].faceIndex, point: hits[0].point } : null;
}
// the singular face nearest to a picked point, within 4% of the diagonal
function nearestSingularity(hit, list) {
  let best = null, bestDistance = 0.04 * model.json.diagonal;
  for (const [f] of list) {
    const d = centroid(f).distanceTo(hit.point);
    if (d < bestDistance) { best = f; bestDistance = d; }
  }
  return best;
}
function tool() { return document.querySelector('input[name="tool"]:checked').value; }

let heatSource = 0;
let firstClick = null;  // the first face of a two-click tool
let drag = null;        // { from, field, t0 } while dragging a singularity
let down = null;

canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0 || !state) return;
  down = { x: event.clientX, y: event.clientY };
  const hit = pick(event.clientX, event.clientY);
  if (!hit || tool() !== 'drag' || event.shiftKey || event.ctrlKey || event.altKey) return;
  let from = nearestSingularity(hit, state.singularities), field = false;
  if (from === null && state.field_singularities.length) {
    from = nearestSingularity(hit, state.field_singularities);
    field = from !== null;
  }
  if (from === null) return;
  drag = { from, field };
  controls.enabled = false;
  canvas.setPointerCapture(event.pointerId);
});

canvas.addEventListener('pointermove', (event) => {
  if (!drag) return;
  const t0 = performance.now();
  const hit = pick(event.clientX, event.clientY);
  if (!hit || hit.face === drag.from) return;
  if (model.boundary.has(hit.face)) return; // a boundary face cannot hold a singularity
  const from = drag.from, to = hit.face;
  drag.from = to; // optimistic: the next move starts there (a refused move resynchronizes below)
  edit(drag.field ? { op: 'move_field_singularity', from, to } : { op: 'move', from, to }, t0, 'drag');
});

function endDrag(event) {
  if (drag) {
    drag = null;
    controls.enabled = true;
    if (canvas.hasPointerCapture(event.pointerId)) canvas.releasePointerCapture(event.pointerId);
  }
}
canvas.addEventListener('pointerup', (event) => {
  const wasDragging = drag !== null;
  endDrag(event);
  if (wasDragging || !down || event.button !== 0) return;
  const moved = Math.hypot(event.clientX - down.x, event.clientY - down.y);
  down = null;
  if (moved > 4) return; // an orbit, not a click
  click(event);
});
canvas.addEventListener('pointercancel', endDrag);

function click(event) {
  const t0 = performance.now();
  const hit = pick(event.clientX, event.clientY);
  if (!hit) return;
  const f = hit.face;
  let mode = tool();
  if (event.shiftKey) mode = 'plus';
  else if (event.ctrlKey || event.altKey) mode = 'minus';
  if (mode === 'plus' || mode === 'minus') {
    edit({ op: 'add', face: f, index: mode === 'plus' ? 1 : -1, family: family() }, t0);
  } else if (mode === 'remove') {
    const s = nearestSingularity(hit, state.singularities);
    if (s === null) showError('no singularity near that point');
    else edit({ op: 'remove', face: s }, t0);
  } else if (mode === 'source') {
    const T = model.json.triangles, P = model.json.positions;
    let best = T[3 * f], bestDistance = Infinity;
    for (let k = 0; k < 3; ++k) {
      const v = T[3 * f + k];
      const d = hit.point.distanceTo(new THREE.Vector3(P[3 * v], P[3 * v + 1], P[3 * v + 2]));
      if (d < bestDistance) { best = v; bestDistance = d; }
    }
    heatSource = best;
    if (ui.field.value.startsWith('heat')) setField(t0);
    else ui.hint.textContent = `heat source: vertex ${best} (choose a heat field)`;
  } else if (mode === 'pair' || mode === 'annihilate' || mode === 'field-pair' || mode === 'field-annihilate') {
    const face = mode === 'pair' || mode === 'field-pair' ? f
      : nearestSingularity(hit, mode === 'annihilate' ? state.singularities : state.field_singularities);
    if (face === null) { showError('no singularity near that point'); return; }
    if (firstClick === null) {
      firstClick = face;
      const unit = fraction(1, state.order);
      ui.hint.textContent = mode === 'pair' ? `+1 at face ${face}: now click where the -1 goes`
        : mode === 'field-pair' ? `field ${unit} at face ${face}: now click where the ${unit.replace('+', '-')} goes`
          : `face ${face}: now click its partner`;
      return;
    }
    const first = firstClick;
    firstClick = null;
    const request = mode === 'pair' ? { op: 'add_pair', plus: first, minus: face, family: family() }
      : mode === 'annihilate' ? { op: 'annihilate', a: first, b: face }
        : mode === 'field-pair' ? { op: 'add_field_pair', plus: first, minus: face }
          : { op: 'annihilate_field', a: first, b: face };
    edit(request, t0);
  }
}
document.querySelectorAll('input[name="tool"]').forEach((input) => input.addEventListener('change', () => { firstClick = null; }));

function setField(t0 = performance.now()) {
  const value = ui.field.value;
  let request;
  if (value.startsWith('axis:')) request = { op: 'field', kind: 'axis', axis: value.slice(5).split(',').map(Number) };
  else if (value.startsWith('heat:')) request = { op: 'field', kind: 'heat', vertex: heatSource, degrees: Number(value.slice(5)) };
  else {
    const [kind, rest] = value.split('@');
    const [order, cones, boundary] = (rest || '').split('+');
    request = { op: 'field', kind, order: Number(order || (kind === 'principal' ? 2 : 1)) };
    if (cones) request.cones = cones;
    if (boundary) request.boundary = boundary;
  }
  return edit(request, t0, `field ${value}`);
}
ui.field.addEventListener('change', () => setField());
ui.stripes.addEventListener('input', () => {
  const max = Number(ui.stripes.dataset.max);
  if (!model || !(max > 1)) return; // the mesh is still loading
  const stripes = Math.min(Math.exp((Number(ui.stripes.value) / 1000) * Math.log(max)), max);
  ui.stripesValue.textContent = stripes.toFixed(1);
  edit({ op: 'frequency', stripes }, performance.now(), 'frequency');
});
ui.mesh.addEventListener('change', () => edit({ op: 'load', name: ui.mesh.value }, performance.now(), 'load'));
document.getElementById('clear').addEventListener('click', () => edit({ op: 'clear' }));
ui.automatic.addEventListener('click', () => edit({ op: 'automatic' }));
ui.quads.addEventListener('change', () => edit({ op: 'quads', on: ui.quads.checked }));
ui.exportQuads.addEventListener('click', () => { window.location.href = `api/export_quads.off?token=${encodeURIComponent(token)}`; });
document.getElementById('export-ply').addEventListener('click', () => { window.location.href = `api/export.ply?token=${encodeURIComponent(token)}`; });
document.getElementById('export-png').addEventListener('click', () => {
  render();
  canvas.toBlob((blob) => {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(blob);
    a.download = 'stripes.png';
    a.click();
  });
});

// ---------------------------------------------------------------- the browser test's script

const params = new URLSearchParams(window.location.search);

function screenOf(f) {
  const p = centroid(f).project(camera);
  const r = canvas.getBoundingClientRect();
  return { x: r.left + (p.x + 1) / 2 * r.width, y: r.top + (1 - p.y) / 2 * r.height };
}
function pointer(type, at, extra = {}) {
  canvas.dispatchEvent(new PointerEvent(type, Object.assign({ clientX: at.x, clientY: at.y, button: 0, buttons: type === 'pointerup' ? 0 : 1, pointerId: 1, bubbles: true, isPrimary: true, pointerType: 'mouse' }, extra)));
}
async function settle() {
  while (busy) await new Promise((resolve) => setTimeout(resolve, 5));
  render();
  await new Promise((resolve) => requestAnimationFrame(resolve));
}
function pictureHash() {
  render();
  const gl = renderer.getContext();
  const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
  const pixels = new Uint8Array(4 * w * h);
  gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  let hash = 2166136261, lit = 0;
  for (let i = 0; i < pixels.length; i += 4) {
    hash = Math.imul(hash ^ pixels[i] ^ (pixels[i + 1] << 8) ^ (pixels[i + 2] << 16), 16777619) >>> 0;
    if (pixels[i] !== 244 || pixels[i + 1] !== 244 || pixels[i + 2] !== 240) ++lit;
  }
  return { hash, lit, pixels: w * h };
}
async function saveFrame(name) {
  render();
  const blob = await new Promise((resolve) => canvas.toBlob(resolve, 'image/png'));
  await api(`api/frame?name=${name}`, { method: 'POST', headers: { 'Content-Type': 'image/png' }, body: blob });
}
// a front-facing interior face near a screen point, with its screen position
function faceNear(x, y) {
  const r = canvas.getBoundingClientRect();
  for (let radius = 0; radius < 200; radius += 5)
    for (let a = 0; a < 8; ++a) {
      const at = { x: r.left + x * r.width + radius * Math.cos(a * Math.PI / 4), y: r.top + y * r.height + radius * Math.sin(a * Math.PI / 4) };
      const hit = pick(at.x, at.y);
      if (hit && !model.boundary.has(hit.face)) return { face: hit.face, at };
    }
  return null;
}

async function selftest() {
  const checks = [];
  const check = (name, ok, detail = '') => checks.push({ name, ok: !!ok, detail: String(detail) });
  await settle();

  // first a mesh with a boundary (a plate with two holes): the quads follow its three loops when
  // the cross field follows them too; then the first mesh again, for the rest
  const first = ui.mesh.value;
  await edit({ op: 'load', name: 'holed_plate.off' });
  await settle();
  ui.field.value = 'trivial@4+smoothest+tangent';
  await setField();
  await edit({ op: 'frequency', stripes: 16 });
  ui.quads.click();
  await settle();
  check('a mesh with a boundary: the cross field along it, the quads following its 3 loops, drawn',
    state.field.boundary === 'tangent' && state.quads.on && state.quads.valid && state.quads.boundary_loops === 3 &&
    quadLines !== null, JSON.stringify(state.quads));
  check('the panel reports the loops', ui.quadStatus.textContent.includes('3 boundary loops followed'), ui.quadStatus.textContent);
  check('the field menu shows the field along the boundary', ui.field.value === 'trivial@4+smoothest+tangent', ui.field.value);
  await saveFrame('editor_quads_boundary');
  ui.quads.click();
  await settle();
  await edit({ op: 'load', name: first });
  await settle();
  check('back to the first mesh, a new session', ui.mesh.value === first && state.version === 0 && !state.quads.on,
    `${ui.mesh.value} version ${state.version}`);
  const initial = pictureHash();
  check('the mesh is drawn', initial.lit > 0.05 * initial.pixels, `${initial.lit} of ${initial.pixels} pixels`);
  await saveFrame('editor_initial');

  // a +1/-1 pair by two real clicks of the pair tool
  document.querySelector('input[name="tool"][value="pair"]').click();
  const a = faceNear(0.42, 0.4), b = faceNear(0.58, 0.6);
  check('two faces under the pointer', a && b && a.face !== b.face, JSON.stringify([a && a.face, b && b.face]));
  for (const p of [a, b]) { pointer('pointerdown', p.at); pointer('pointerup', p.at); }
  await settle();
  const afterPair = pictureHash();
  check('the picture changed after the click', afterPair.hash !== initial.hash);
  const listed = JSON.stringify(state.singularities.map(([f, k]) => [f, k]).sort((x, y) => x[0] - y[0]));
  const expected = JSON.stringify([[a.face, 1], [b.face, -1]].sort((x, y) => x[0] - y[0]));
  check('the reported singularities are the clicked faces', listed === expected, `${listed} vs ${expected}`);
  check('the page lists them', ui.singularities.textContent.includes(`face ${a.face}: +1`) && ui.singularities.textContent.includes(`face ${b.face}: -1`), ui.singularities.textContent);
  await saveFrame('editor_pair');

  // drag the -1 in small steps: one move (a re-solve) per face crossed
  document.querySelector('input[name="tool"][value="drag"]').click();
  const start = screenOf(b.face), end = { x: start.x - 0.25 * canvas.clientWidth, y: start.y + 0.02 * canvas.clientHeight };
  pointer('pointerdown', start);
  check('the drag grabbed the -1', drag !== null && drag.from === b.face);
  const steps = 6, dragLog = latencyLog.length;
  // a film strip of the drag at a third of the size, for the manual
  const strip = document.createElement('canvas');
  const fw = Math.floor(canvas.width / 3), fh = Math.floor(canvas.height / 3);
  strip.width = steps * fw;
  strip.height = fh;
  for (let i = 1; i <= steps; ++i) {
    pointer('pointermove', { x: start.x + (end.x - start.x) * i / steps, y: start.y + (end.y - start.y) * i / steps });
    await settle();
    await saveFrame(`editor_drag_${i}`);
    strip.getContext('2d').drawImage(canvas, (i - 1) * fw, 0, fw, fh);
  }
  const stripBlob = await new Promise((resolve) => strip.toBlob(resolve, 'image/png'));
  await api('api/frame?name=editor_drag_strip', { method: 'POST', headers: { 'Content-Type': 'image/png' }, body: stripBlob });
  pointer('pointerup', end);
  await settle();
  const minus = state.singularities.filter(([f, k]) => k < 0);
  check('the -1 moved', minus.length === 1 && minus[0][0] !== b.face, JSON.stringify(state.singularities));
  check('the +1 stayed', state.singularities.some(([f, k]) => f === a.face && k === 1));
  const drags = latencyLog.slice(dragLog).filter((l) => l.label === 'drag');
  check('each drag step re-solved', drags.length >= 2, drags.length);

  // annihilate the pair by two clicks
  document.querySelector('input[name="tool"][value="annihilate"]').click();
  for (const f of [a.face, minus[0] ? minus[0][0] : b.face]) { const p = screenOf(f); pointer('pointerdown', p); pointer('pointerup', p); }
  await settle();
  check('the pair annihilated', state.singularities.length === 0, JSON.stringify(state.singularities));
  check('the picture is back to the initial one', pictureHash().hash === initial.hash);

  // a refused edit shows its message and keeps the state
  const before = JSON.stringify(state.singularities);
  await edit({ op: 'move', from: 0, to: 1 });
  await settle();
  check('a refused edit is explained on the page', ui.error.textContent.includes('holds no singularity'), ui.error.textContent);
  check('a refused edit keeps the state', JSON.stringify(state.singularities) === before);

  // the frequency slider, moved as a user would (an input event)
  const stripesBefore = state.stripes;
  ui.stripes.value = String(Number(ui.stripes.value) + 150);
  ui.stripes.dispatchEvent(new Event('input'));
  await settle();
  check('the slider changed the frequency', state.stripes > 1.2 * stripesBefore, `${stripesBefore} -> ${state.stripes}`);

  // a line field with singularities of its own (+1/2 each), one of them dragged like the stripes'
  ui.field.value = 'trivial@2';
  await setField();
  await settle();
  const branchOf = () => JSON.stringify(state.branch_faces.map(([f, k]) => [f, k]).sort((x, y) => x[0] - y[0]));
  const fieldOf = () => JSON.stringify(state.field_singularities.slice().sort((x, y) => x[0] - y[0]));
  check('the trivial line field: four +1/2, drawn as branch faces', state.order === 2 && state.field_singularities.length === 4 &&
    branchOf() === fieldOf() && state.overlay === 3 * state.branch_faces.length && overlay !== null, fieldOf());
  await saveFrame('editor_line_field');
  const r = canvas.getBoundingClientRect();
  const grabbable = state.field_singularities.map(([f]) => f).find((f) => {
    const at = screenOf(f);
    const hit = pick(at.x, at.y);
    return at.x > r.left + 0.2 * r.width && at.x < r.right - 0.2 * r.width && at.y > r.top + 0.1 * r.height &&
      at.y < r.bottom - 0.1 * r.height && hit && hit.point.distanceTo(centroid(f)) < 0.02 * model.json.diagonal;
  });
  check('a field singularity in view', grabbable !== undefined, fieldOf());
  if (grabbable !== undefined) {
    const from = screenOf(grabbable), to = { x: from.x + 0.12 * r.width, y: from.y + 0.05 * r.height };
    document.querySelector('input[name="tool"][value="drag"]').click();
    pointer('pointerdown', from);
    check('the drag grabbed the field singularity', drag !== null && drag.field && drag.from === grabbable);
    for (let i = 1; i <= 4; ++i) {
      pointer('pointermove', { x: from.x + (to.x - from.x) * i / 4, y: from.y + (to.y - from.y) * i / 4 });
      await settle();
    }
    pointer('pointerup', to);
    await settle();
    const moved = state.field_singularities.map(([f]) => f);
    check('the +1/2 moved, and the stripes\' branch faces with it', !moved.includes(grabbable) && moved.length === 4 &&
      branchOf() === fieldOf(), `${grabbable} -> ${fieldOf()}`);
    await saveFrame('editor_line_field_dragged');
  }
  // a cross field's quad preview: the trivial connection's eight +1/4 cones, the box ticked, the
  // quads drawn; a cone dragged, the quads follow
  ui.field.value = 'trivial@4';
  await setField();
  await edit({ op: 'frequency', stripes: 30 });
  ui.quads.click();
  await settle();
  const quadsOk = () => state.quads.on && state.quads.valid && quadLines !== null &&
    state.quad_edges === 2 * state.quads.faces && state.quads.irregular_vertices === state.field_singularities.length;
  check('the quad preview: quads whose irregular vertices are the cones, drawn', quadsOk(), JSON.stringify(state.quads));
  check('the panel reports the quads', ui.quadStatus.textContent.includes(`${state.quads.faces} quads`), ui.quadStatus.textContent);
  await saveFrame('editor_quads');
  const cone = state.field_singularities.map(([f]) => f).find((f) => {
    const at = screenOf(f);
    const hit = pick(at.x, at.y);
    return at.x > r.left + 0.2 * r.width && at.x < r.right - 0.2 * r.width && at.y > r.top + 0.1 * r.height &&
      at.y < r.bottom - 0.1 * r.height && hit && hit.point.distanceTo(centroid(f)) < 0.02 * model.json.diagonal;
  });
  if (cone !== undefined) {
    const from = screenOf(cone), to = { x: from.x + 0.06 * r.width, y: from.y + 0.03 * r.height };
    document.querySelector('input[name="tool"][value="drag"]').click();
    pointer('pointerdown', from);
    for (let i = 1; i <= 3; ++i) {
      pointer('pointermove', { x: from.x + (to.x - from.x) * i / 3, y: from.y + (to.y - from.y) * i / 3 });
      await settle();
    }
    pointer('pointerup', to);
    await settle();
    check('a cone dragged, the quads followed', !state.field_singularities.some(([f]) => f === cone) && state.quads.on &&
      (state.quads.valid ? quadsOk() : state.quads.problem.length > 0), JSON.stringify(state.quads));
    await saveFrame('editor_quads_dragged');
  }
  ui.quads.click();
  await settle();
  check('the quad preview off: no quad lines', !state.quads.on && quadLines === null, JSON.stringify(state.quads));

  // a field with singularities of its own, for the final picture
  ui.field.value = 'smoothest';
  await setField();
  await settle();
  check('the smoothest field', state.field.kind === 'smoothest', JSON.stringify(state.field));
  await saveFrame('editor_smoothest');
  document.querySelector('input[name="tool"][value="pair"]').click();
  for (const p of [a, b]) { pointer('pointerdown', p.at); pointer('pointerup', p.at); }
  await settle();
  await saveFrame('editor_final');

  const pass = checks.every((c) => c.ok);
  // what the page did, for the test to compare with the server's own state
  const did = { plus: a.face, minus: b.face, edits: acceptedEdits, stripes: state.stripes, field: state.field.kind };
  const result = { pass, checks, did, latency: latencyLog, faces: model.json.faces };
  ui.selftest.textContent = 'SELFTEST ' + JSON.stringify(result);
  document.title = pass ? 'SELFTEST PASS' : 'SELFTEST FAIL';
}

start().then(() => {
  if (params.get('selftest') === '1')
    return selftest().catch((e) => { ui.selftest.textContent = 'SELFTEST ' + JSON.stringify({ pass: false, error: String(e && e.stack || e) }); });
}).catch((e) => showError(`cannot start: ${e.message}`));
