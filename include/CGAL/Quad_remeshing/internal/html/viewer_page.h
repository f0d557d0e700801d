// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fixed parts of the HTML report: style, start-up guard and the viewer module (three.js).

#ifndef CGAL_QUAD_REMESHING_INTERNAL_HTML_VIEWER_PAGE_H
#define CGAL_QUAD_REMESHING_INTERNAL_HTML_VIEWER_PAGE_H

namespace CGAL {
namespace Quad_remeshing {
namespace internal {
namespace html {

inline const char* page_style()
{
  return R"CSS(
html, body { margin: 0; height: 100%; font: 13px/1.35 system-ui, sans-serif; color: #222; }
body { display: flex; }
#view { flex: 1; position: relative; min-width: 0; background: #ffffff; }
#view canvas { display: block; }
#help { position: absolute; left: 8px; bottom: 6px; color: #777; font-size: 11px; pointer-events: none; }
#side { width: 390px; overflow-y: auto; border-left: 1px solid #ccc; padding: 8px 12px; box-sizing: border-box; background: #f7f7f7; }
h1 { font-size: 16px; margin: 4px 0 8px; }
h2 { font-size: 14px; margin: 14px 0 6px; border-bottom: 1px solid #ccc; }
h3 { font-size: 13px; margin: 8px 0 3px; }
h4 { font-size: 12px; margin: 6px 0 2px; }
.layer { margin: 3px 0; }
.legend { margin: 2px 0 4px 22px; font-size: 11px; }
.swatch { display: inline-block; width: 10px; height: 10px; margin: 0 3px 0 8px; border: 1px solid #666; }
.colorbar { margin: 2px 0 6px 22px; font-size: 11px; }
.colorbar canvas { display: block; border: 1px solid #999; }
table { border-collapse: collapse; font-size: 12px; margin-bottom: 6px; }
td, th { padding: 1px 6px; text-align: left; border-bottom: 1px solid #e3e3e3; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
.bar { display: inline-block; height: 8px; background: #4a7bd0; }
pre { font-size: 11px; max-height: 300px; overflow: auto; background: #fff; border: 1px solid #ddd; padding: 4px; }
)CSS";
}

// A classic script runs before the module: it records every error, and marks the page as failed if
// the module never finished (a failed import does not reach window.onerror).
inline const char* page_guard_script()
{
  return R"JS(
document.documentElement.dataset.status = 'loading';
window.qrFail = function (msg) {
  if (!String(document.documentElement.dataset.status).startsWith('error'))
    document.documentElement.dataset.status = 'error:' + msg;
};
window.addEventListener('error', (e) => qrFail(e.message || 'script error'));
window.addEventListener('unhandledrejection', (e) => qrFail(String(e.reason)));
const qrConsoleError = console.error.bind(console);
console.error = function (...args) { qrFail(args.map(String).join(' ')); qrConsoleError(...args); };
window.addEventListener('load', () => {
  if (document.documentElement.dataset.status === 'loading') qrFail('the viewer module did not run');
});
)JS";
}

inline const char* viewer_module_script()
{
  return R"JS(
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const scene_data = JSON.parse(document.getElementById('qr-scene').textContent);
const report = JSON.parse(document.getElementById('qr-report').textContent);

const color_maps = {
  viridis: [[0.267, 0.005, 0.329], [0.283, 0.141, 0.458], [0.254, 0.265, 0.530], [0.207, 0.372, 0.553],
            [0.164, 0.471, 0.558], [0.128, 0.567, 0.551], [0.135, 0.659, 0.518], [0.267, 0.749, 0.441],
            [0.478, 0.821, 0.318], [0.741, 0.873, 0.150], [0.993, 0.906, 0.144]],
  red_to_green: [[0.80, 0.10, 0.10], [0.95, 0.55, 0.15], [0.98, 0.90, 0.30], [0.55, 0.80, 0.35], [0.10, 0.60, 0.25]],
  blue_to_red: [[0.23, 0.30, 0.75], [0.87, 0.87, 0.87], [0.71, 0.02, 0.15]]
};
function map_color(name, t) {
  const m = color_maps[name] || color_maps.viridis;
  if (!Number.isFinite(t)) return [0.6, 0.6, 0.6];
  t = Math.min(1, Math.max(0, t)) * (m.length - 1);
  const i = Math.min(m.length - 2, Math.floor(t)), u = t - i;
  return [0, 1, 2].map((k) => m[i][k] * (1 - u) + m[i + 1][k] * u);
}
const css = (c) => `rgb(${Math.round(c[0] * 255)},${Math.round(c[1] * 255)},${Math.round(c[2] * 255)})`;
// colours are given in sRGB; three.js works in linear space
const tmp = new THREE.Color();
function push_srgb(out, c) { tmp.setRGB(c[0], c[1], c[2], THREE.SRGBColorSpace); out.push(tmp.r, tmp.g, tmp.b); }
const rgb = (c) => [c[0] / 255, c[1] / 255, c[2] / 255];

const view = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio || 1);
renderer.setClearColor(0xffffff);
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(35, 1, 1e-3, 1e3);
scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 1.6));
const head_light = new THREE.DirectionalLight(0xffffff, 1.6);
camera.add(head_light);
head_light.position.set(0.3, 0.5, 1);
scene.add(camera);

function polygons_object(p) {
  const pos = p.points, faces = p.faces;
  const xyz = [], col = [], edges = new Set(), wire = [];
  const lo = p.range[0], hi = p.range[1];
  for (let f = 0; f < faces.length; ++f) {
    const face = faces[f];
    let c = p.color;
    if (p.face_colors.length) c = rgb(p.face_colors[f]);
    else if (p.face_scalars.length) c = map_color(p.color_map, hi > lo ? (p.face_scalars[f] - lo) / (hi - lo) : 0.5);
    else c = rgb(c);
    // fan triangulation: faces are planar enough for display, and any degree is accepted
    for (let k = 1; k + 1 < face.length; ++k)
      for (const v of [face[0], face[k], face[k + 1]]) { xyz.push(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]); push_srgb(col, c); }
    if (p.wireframe)
      for (let k = 0; k < face.length; ++k) {
        const a = face[k], b = face[(k + 1) % face.length], key = a < b ? a + ',' + b : b + ',' + a;
        if (edges.has(key)) continue;
        edges.add(key);
        wire.push(pos[3 * a], pos[3 * a + 1], pos[3 * a + 2], pos[3 * b], pos[3 * b + 1], pos[3 * b + 2]);
      }
  }
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(xyz, 3));
  g.setAttribute('color', new THREE.Float32BufferAttribute(col, 3));
  g.computeVertexNormals();
  // the offset keeps the wireframe and the lines drawn on the surface visible
  const material = new THREE.MeshLambertMaterial({ vertexColors: true, side: THREE.DoubleSide, flatShading: true,
    polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
    transparent: p.opacity < 1, opacity: p.opacity });
  const group = new THREE.Group();
  group.add(new THREE.Mesh(g, material));
  if (wire.length) {
    const wg = new THREE.BufferGeometry();
    wg.setAttribute('position', new THREE.Float32BufferAttribute(wire, 3));
    const wc = []; push_srgb(wc, rgb(p.wireframe_color));
    group.add(new THREE.LineSegments(wg, new THREE.LineBasicMaterial({ color: new THREE.Color(wc[0], wc[1], wc[2]) })));
  }
  return group;
}

function segments_object(s) {
  const col = [], n = s.endpoints.length / 6;
  for (let i = 0; i < n; ++i) {
    const c = rgb(s.colors.length ? s.colors[i] : s.color);
    push_srgb(col, c); push_srgb(col, c);
  }
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(s.endpoints, 3));
  g.setAttribute('color', new THREE.Float32BufferAttribute(col, 3));
  return new THREE.LineSegments(g, new THREE.LineBasicMaterial({ vertexColors: true }));
}

let disc = null;
function disc_texture() {
  if (disc) return disc;
  const c = document.createElement('canvas'); c.width = c.height = 64;
  const ctx = c.getContext('2d');
  ctx.beginPath(); ctx.arc(32, 32, 28, 0, 2 * Math.PI); ctx.fillStyle = '#fff'; ctx.fill();
  ctx.lineWidth = 6; ctx.strokeStyle = '#000'; ctx.stroke();
  disc = new THREE.CanvasTexture(c);
  return disc;
}
function points_object(p) {
  const col = [], n = p.points.length / 3;
  for (let i = 0; i < n; ++i) push_srgb(col, rgb(p.colors.length ? p.colors[i] : p.color));
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.Float32BufferAttribute(p.points, 3));
  g.setAttribute('color', new THREE.Float32BufferAttribute(col, 3));
  return new THREE.Points(g, new THREE.PointsMaterial({ size: p.size, sizeAttenuation: false, vertexColors: true,
    map: disc_texture(), alphaTest: 0.5 }));
}

const side_layers = document.getElementById('qr-layers');
const box = new THREE.Box3();
const objects = [], layer_divs = [];
// "#layers=a,b" in the address shows these layers only (names URL-encoded), e.g. for screenshots
const shown = (() => {
  const m = /(?:^#|&)layers=([^&]*)/.exec(window.location.hash);
  return m ? new Set(m[1].split(',').map((x) => decodeURIComponent(x))) : null;
})();
for (const layer of scene_data.layers) {
  if (shown) layer.visible = shown.has(layer.name);
  const group = new THREE.Group();
  if (layer.polygons.faces.length) group.add(polygons_object(layer.polygons));
  if (layer.segments.endpoints.length) group.add(segments_object(layer.segments));
  if (layer.points.points.length) group.add(points_object(layer.points));
  group.visible = layer.visible;
  group.name = layer.name;
  scene.add(group);
  objects.push(group);
  box.expandByObject(group);

  const div = document.createElement('div'); div.className = 'layer';
  // what the layer holds, for tests: data-faces, data-segments, data-points (data-pixels is set below)
  div.dataset.layerName = layer.name;
  div.dataset.faces = String(layer.polygons.faces.length);
  div.dataset.segments = String(layer.segments.endpoints.length / 6);
  div.dataset.points = String(layer.points.points.length / 3);
  layer_divs.push(div);
  const label = document.createElement('label');
  const box_input = document.createElement('input'); box_input.type = 'checkbox'; box_input.checked = layer.visible;
  box_input.addEventListener('change', () => { group.visible = box_input.checked; render(); });
  label.append(box_input, ' ' + layer.name + ' ');
  const count = document.createElement('small'); count.style.color = '#777';
  const parts = [];
  if (layer.polygons.faces.length) parts.push(layer.polygons.faces.length + ' faces');
  if (layer.segments.endpoints.length) parts.push(layer.segments.endpoints.length / 6 + ' segments');
  if (layer.points.points.length) parts.push(layer.points.points.length / 3 + ' points');
  count.textContent = '(' + parts.join(', ') + ')';
  label.append(count);
  div.append(label);
  if (layer.legend.length) {
    const legend = document.createElement('div'); legend.className = 'legend';
    for (const e of layer.legend) {
      const sw = document.createElement('span'); sw.className = 'swatch'; sw.style.background = css(rgb(e.color));
      legend.append(sw, e.label);
    }
    div.append(legend);
  }
  const p = layer.polygons;
  if (p.face_scalars.length && !p.face_colors.length) {
    const bar = document.createElement('div'); bar.className = 'colorbar';
    const c = document.createElement('canvas'); c.width = 240; c.height = 10;
    const ctx = c.getContext('2d');
    for (let x = 0; x < c.width; ++x) { ctx.fillStyle = css(map_color(p.color_map, x / (c.width - 1))); ctx.fillRect(x, 0, 1, c.height); }
    bar.append(p.scalar_name + ':', c, `${p.range[0].toPrecision(3)} … ${p.range[1].toPrecision(3)}`);
    div.append(bar);
  }
  side_layers.append(div);
}

const controls = new OrbitControls(camera, renderer.domElement);
function fit() {
  const center = box.isEmpty() ? new THREE.Vector3() : box.getCenter(new THREE.Vector3());
  const radius = box.isEmpty() ? 1 : Math.max(1e-9, box.getSize(new THREE.Vector3()).length() / 2);
  const distance = radius / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2)) * 1.05;
  camera.near = distance / 100; camera.far = distance * 10;
  camera.position.copy(center).add(new THREE.Vector3(0.55, 0.45, 1).normalize().multiplyScalar(distance));
  camera.updateProjectionMatrix();
  controls.target.copy(center);
  controls.update();
}
function render() { renderer.render(scene, camera); }
function resize() {
  const w = Math.max(1, view.clientWidth), h = Math.max(1, view.clientHeight);
  renderer.setSize(w, h);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
  render();
}
controls.addEventListener('change', render);
window.addEventListener('resize', resize);
document.getElementById('qr-fit').addEventListener('click', () => { fit(); render(); });

// histograms, drawn as bars on 2D canvases
const hist_div = document.getElementById('qr-histograms');
for (const h of scene_data.histograms) {
  const title = document.createElement('div');
  title.innerHTML = `<b></b> <small></small>`;
  title.querySelector('b').textContent = h.title;
  title.querySelector('small').textContent = `${h.count} values, mean ${Number(h.mean).toPrecision(4)}`;
  const c = document.createElement('canvas'); c.width = 360; c.height = 110;
  const ctx = c.getContext('2d'), n = h.counts.length, top = Math.max(1, ...h.counts);
  const w = (c.width - 10) / Math.max(1, n);
  ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, c.width, c.height);
  ctx.fillStyle = '#4a7bd0';
  for (let i = 0; i < n; ++i) {
    const bh = (c.height - 22) * h.counts[i] / top;
    ctx.fillRect(5 + i * w, c.height - 16 - bh, Math.max(1, w - 1), bh);
  }
  ctx.fillStyle = '#333'; ctx.font = '10px sans-serif';
  ctx.fillText(Number(h.min).toPrecision(3), 4, c.height - 4);
  const right = Number(h.max).toPrecision(3);
  ctx.fillText(right, c.width - 4 - ctx.measureText(right).width, c.height - 4);
  ctx.fillText('max bin ' + top, 4, 10);
  hist_div.append(title, c);
}

// the run's report: per-stage timings, then the figures of each stage
const report_div = document.getElementById('qr-report-tables');
function table(rows, header) {
  const t = document.createElement('table');
  if (header) { const tr = t.insertRow(); for (const h of header) { const th = document.createElement('th'); th.textContent = h; tr.append(th); } }
  for (const r of rows) {
    const tr = t.insertRow();
    r.forEach((v, i) => { const td = tr.insertCell(); if (v instanceof Node) td.append(v); else { td.textContent = v; if (i > 0) td.className = 'num'; } });
  }
  return t;
}
const fmt = (v) => typeof v === 'number' && !Number.isInteger(v) ? v.toPrecision(4) : String(v);
// Stage timings come from "stages": [{name, seconds, ...}] (the command-line program's report) and
// from top-level objects holding "seconds"; every object is then shown as a table of its scalars.
const is_object = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const scalar_rows = (o) => Object.entries(o).filter(([, v]) => v === null || typeof v !== 'object').map(([k, v]) => [k, fmt(v)]);
function add_tables(title, o, depth) {
  const rows = scalar_rows(o);
  if (rows.length) {
    const h = document.createElement(depth > 1 ? 'h4' : 'h3'); h.textContent = title || 'run'; report_div.append(h);
    report_div.append(table(rows));
  }
  for (const [k, v] of Object.entries(o)) {
    if (is_object(v)) add_tables(title ? title + ' / ' + k : k, v, depth + 1);
    else if (Array.isArray(v)) v.forEach((x, i) => { if (is_object(x)) add_tables((title ? title + ' / ' : '') + k + ' / ' + (x.name ?? i), x, depth + 1); });
  }
}
if (is_object(report)) {
  const timed = [];
  if (Array.isArray(report.stages))
    for (const s of report.stages) if (is_object(s) && typeof s.seconds === 'number') timed.push([String(s.name ?? timed.length), s.seconds]);
  for (const [k, v] of Object.entries(report)) if (is_object(v) && typeof v.seconds === 'number') timed.push([k, v.seconds]);
  // the summary above the histograms: the timings, then the quality of the output
  const summary_div = document.getElementById('qr-summary');
  if (timed.length) {
    const h = document.createElement('h3'); h.textContent = 'Timings'; summary_div.append(h);
    const longest = Math.max(1e-12, ...timed.map(([, t]) => t));
    const total = timed.reduce((a, [, t]) => a + t, 0);
    summary_div.append(table(timed.map(([k, t]) => {
      const bar = document.createElement('span'); bar.className = 'bar'; bar.style.width = (80 * t / longest) + 'px';
      return [k, t.toFixed(3) + ' s', bar];
    }).concat([['total', total.toFixed(3) + ' s', '']]), ['stage', 'time', '']));
  }
  const quality = is_object(report.output) && is_object(report.output.quality) ? report.output.quality : null;
  if (quality) {
    const h = document.createElement('h3'); h.textContent = 'Quality of the output'; summary_div.append(h);
    summary_div.append(table(scalar_rows(quality)));
  }
  add_tables('', report, 0);
}
document.getElementById('qr-report-json').textContent = JSON.stringify(report, null, 2);

fit();
resize();
// Each layer alone: the pixels it covers in the default view (a layer with elements and no pixel is a
// bug of the viewer or of the data); the count goes to data-pixels of its entry in the layer list.
{
  const gl = renderer.getContext(), w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
  const buffer = new Uint8Array(4 * w * h);
  const visible = objects.map((o) => o.visible);
  objects.forEach((o, i) => {
    objects.forEach((p, j) => { p.visible = i === j; });
    render();
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, buffer);
    let pixels = 0;
    for (let k = 0; k < buffer.length; k += 4) if (buffer[k] < 250 || buffer[k + 1] < 250 || buffer[k + 2] < 250) ++pixels;
    layer_divs[i].dataset.pixels = String(pixels);
  });
  objects.forEach((o, i) => { o.visible = visible[i]; });
  render();
}
const drawn = renderer.info.render.triangles + renderer.info.render.lines + renderer.info.render.points;
document.documentElement.dataset.layers = String(objects.length);
document.documentElement.dataset.drawn = String(drawn);
if (objects.some((o) => o.visible) && drawn === 0) qrFail('nothing was drawn');
else if (document.documentElement.dataset.status === 'loading') document.documentElement.dataset.status = 'ok';
)JS";
}

} // namespace html
} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_HTML_VIEWER_PAGE_H
