// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Browser test of the HTML report: opens REPORT.html offline in headless Chromium, requires that the
// page reports data-status="ok" (no script or console error, something drawn), that every layer holding
// elements covers pixels when drawn alone (the page measures it: data-pixels of its entry in the layer
// list) and that each expected layer is there and not empty; takes a screenshot, decodes it (node's
// zlib only) and requires a drawn mesh in the viewer area. Fails, never skips, when the browser is
// missing: the test setup installs it.
//
//   node browser_test.mjs REPORT.html SCREENSHOT.png [--expect-layers 'A|B|...']
//                         [--layers-screenshot 'A|B|...' SCREENSHOT2.png]
// --layers-screenshot takes a second screenshot showing these layers only (the page's #layers= address).
// The browser is $CHROMIUM, else the first of chromium, chromium-browser, google-chrome in PATH.

import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { delimiter, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { inflateSync } from 'node:zlib';

const WIDTH = 1400, HEIGHT = 900, SIDE_PANEL = 390;

function fail(message) {
  console.error('browser_test: FAILED: ' + message);
  process.exit(1);
}

function find_browser() {
  if (process.env.CHROMIUM) return process.env.CHROMIUM;
  for (const name of ['chromium', 'chromium-browser', 'google-chrome']) {
    for (const dir of (process.env.PATH || '').split(delimiter)) {
      const p = join(dir, name);
      if (dir && existsSync(p) && statSync(p).isFile()) return p;
    }
  }
  fail('no Chromium found (set CHROMIUM or install Debian\'s chromium: scripts/setup.sh does)');
}

// One headless run on a fresh profile, without any network activity of the browser itself.
function run_browser(browser, url, extra) {
  const profile = mkdtempSync(join(tmpdir(), 'qr-chromium-'));
  try {
    const r = spawnSync(browser, [
      '--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--no-default-browser-check',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--disable-extensions', '--disable-default-apps', '--metrics-recording-only', '--mute-audio',
      // WebGL without a GPU: SwiftShader, which recent Chromium only uses when asked to
      '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
      '--user-data-dir=' + profile, `--window-size=${WIDTH},${HEIGHT}`, '--hide-scrollbars',
      '--virtual-time-budget=20000', ...extra, url], { encoding: 'utf8', timeout: 180000, maxBuffer: 1 << 28 });
    if (r.error) fail(`cannot run ${browser}: ${r.error.message}`);
    if (r.status !== 0) fail(`${browser} exited with status ${r.status}:\n${r.stderr}`);
    return r.stdout;
  } finally {
    rmSync(profile, { recursive: true, force: true });
  }
}

// A PNG decoder for what Chromium writes: 8-bit RGB or RGBA, not interlaced.
function decode_png(buffer) {
  const signature = Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]);
  if (!buffer.subarray(0, 8).equals(signature)) fail('the screenshot is not a PNG file');
  let pos = 8, width = 0, height = 0, depth = 0, type = 0, interlace = 0;
  const idat = [];
  while (pos + 8 <= buffer.length) {
    const length = buffer.readUInt32BE(pos), name = buffer.toString('latin1', pos + 4, pos + 8);
    const data = buffer.subarray(pos + 8, pos + 8 + length);
    if (name === 'IHDR') {
      width = data.readUInt32BE(0); height = data.readUInt32BE(4);
      depth = data[8]; type = data[9]; interlace = data[12];
    } else if (name === 'IDAT') idat.push(data);
    else if (name === 'IEND') break;
    pos += 12 + length;
  }
  if (depth !== 8 || (type !== 2 && type !== 6) || interlace !== 0)
    fail(`unsupported PNG (bit depth ${depth}, colour type ${type}, interlace ${interlace})`);
  const channels = type === 6 ? 4 : 3, stride = width * channels;
  const raw = inflateSync(Buffer.concat(idat));
  if (raw.length !== height * (stride + 1)) fail('truncated PNG data');
  const pixels = Buffer.alloc(height * stride);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    const out = pixels.subarray(y * stride, (y + 1) * stride);
    const up = y > 0 ? pixels.subarray((y - 1) * stride, y * stride) : Buffer.alloc(stride);
    for (let i = 0; i < stride; ++i) {
      const a = i >= channels ? out[i - channels] : 0, b = up[i], c = i >= channels ? up[i - channels] : 0;
      let v;
      switch (filter) {
        case 0: v = 0; break;
        case 1: v = a; break;
        case 2: v = b; break;
        case 3: v = (a + b) >> 1; break;
        case 4: { const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
                  v = pa <= pb && pa <= pc ? a : pb <= pc ? b : c; break; }
        default: fail('bad PNG filter ' + filter);
      }
      out[i] = (line[i] + v) & 255;
    }
  }
  return { width, height, channels, pixels };
}

const usage = "usage: node browser_test.mjs REPORT.html SCREENSHOT.png [--expect-layers 'A|B'] " +
              "[--layers-screenshot 'A|B' SCREENSHOT2.png]";
const [report_arg, screenshot_arg, ...options] = process.argv.slice(2);
if (!report_arg || !screenshot_arg) fail(usage);
let expected_layers = [], extra_layers = null, extra_screenshot = null;
for (let i = 0; i < options.length; ++i) {
  if (options[i] === '--expect-layers' && i + 1 < options.length) expected_layers = options[++i].split('|');
  else if (options[i] === '--layers-screenshot' && i + 2 < options.length) {
    extra_layers = options[++i].split('|'); extra_screenshot = resolve(options[++i]);
  } else fail(usage);
}
const report = resolve(report_arg), screenshot = resolve(screenshot_arg);
if (!existsSync(report)) fail('no report ' + report + ' (the html_report test writes it)');
const browser = find_browser();
const url = pathToFileURL(report).href;

// 1. the page says it rendered without error
const dom = run_browser(browser, url, ['--dump-dom']);
const html_tag = (dom.match(/<html[^>]*>/) || [''])[0];
const status = (html_tag.match(/data-status="([^"]*)"/) || [null, null])[1];
if (status !== 'ok') fail(`the page status is ${JSON.stringify(status)}, expected "ok"`);
const layers = Number((html_tag.match(/data-layers="(\d+)"/) || [0, 0])[1]);
const drawn = Number((html_tag.match(/data-drawn="(\d+)"/) || [0, 0])[1]);
if (!(layers > 0) || !(drawn > 0)) fail(`nothing drawn (layers ${layers}, primitives ${drawn})`);

// 2. every layer: what it holds and the pixels it covers alone
const unescape = (t) => t.replace(/&quot;/g, '"').replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&amp;/g, '&');
const attribute = (tag, name) => { const m = tag.match(new RegExp(' ' + name + '="([^"]*)"')); return m ? unescape(m[1]) : null; };
const entries = new Map(), tags = dom.match(/<div class="layer"[^>]*>/g) || [], summary = [];
if (tags.length !== layers) fail(`${tags.length} layers listed, ${layers} in the scene`);
for (const tag of tags) {
  const name = attribute(tag, 'data-layer-name'), e = { faces: 0, segments: 0, points: 0, pixels: -1 };
  for (const k of Object.keys(e)) e[k] = Number(attribute(tag, 'data-' + k) ?? -1);
  const elements = e.faces + e.segments + e.points;
  if (!(e.pixels >= 0)) fail(`layer '${name}': no pixel count`);
  if (elements > 0 && e.pixels === 0) fail(`layer '${name}' holds ${elements} elements but covers no pixel`);
  summary.push(`${name}: ${e.faces} faces, ${e.segments} segments, ${e.points} points, ${e.pixels} px`);
  entries.set(name, e);
}
for (const name of expected_layers) {
  const e = entries.get(name);
  if (!e) fail(`expected layer '${name}' is missing (layers: ${[...entries.keys()].join(', ')})`);
  if (e.faces + e.segments + e.points === 0) fail(`expected layer '${name}' is empty`);
}
console.log('browser_test: layers\n  ' + summary.join('\n  '));

// 3. the mesh is visible: enough non-white pixels, in many colours (shading), in the viewer area
function check_screenshot(page_url, file) {
  rmSync(file, { force: true });
  run_browser(browser, page_url, ['--screenshot=' + file]);
  if (!existsSync(file)) fail('no screenshot written');
  const png = decode_png(readFileSync(file));
  const view_width = png.width - Math.round(SIDE_PANEL * png.width / WIDTH);
  let drawn_pixels = 0;
  const colours = new Set();
  for (let y = 0; y < png.height; ++y)
    for (let x = 0; x < view_width; ++x) {
      const i = (y * png.width + x) * png.channels;
      const r = png.pixels[i], g = png.pixels[i + 1], b = png.pixels[i + 2];
      if (r < 235 || g < 235 || b < 235) { ++drawn_pixels; colours.add((r >> 3) << 10 | (g >> 3) << 5 | (b >> 3)); }
    }
  const fraction = drawn_pixels / (view_width * png.height);
  if (fraction < 0.05) fail(`${file}: the viewer area is nearly empty (${(100 * fraction).toFixed(2)}% drawn)`);
  if (fraction > 0.95) fail(`${file}: the viewer area is filled (${(100 * fraction).toFixed(2)}% drawn): no mesh in view`);
  if (colours.size < 50) fail(`${file}: only ${colours.size} colours in the viewer area: the mesh is not shaded`);
  return `${(100 * fraction).toFixed(1)}% of the viewer drawn in ${colours.size} colours; screenshot ${file}`;
}
let message = `browser_test: ok: ${layers} layers, ${drawn} primitives, ` + check_screenshot(url, screenshot);
if (extra_layers) {
  for (const name of extra_layers) if (!entries.has(name)) fail(`--layers-screenshot: no layer '${name}'`);
  message += '; ' + check_screenshot(url + '#layers=' + extra_layers.map(encodeURIComponent).join(','), extra_screenshot);
}
console.log(message);
