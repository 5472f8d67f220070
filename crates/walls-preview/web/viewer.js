// The viewer of walls-preview's interactive page (crates/walls-preview/src/html.rs).
//
// The page holds a movie as JSON in <script id="walls-data" type="application/json">.
// Every position is relative to the centre of the box around the whole movie and in
// units of its size (the longest side), so the scene is about 1 across whatever the
// file's length unit:
//
//   { times: [t0, t1, ...], steps: [step or null, ...],   // the frames (pkdgrav units)
//     readout: { time: [name, per], length: [name, per], withPkdgrav },  // labels
//     centre: [x, y, z], size, sizeLabel,                // the box, in pkdgrav units
//     trails,                                            // frames of path drawn, or 0
//     walls: [{ index, type, color: "#rrggbb", opacity,
//               positions: [x, y, z, ...],   // the first frame's mesh about its anchor
//               indices: [a, b, c, ...],     // its triangles
//               origins: [x, y, z, ...],     // its anchor in each frame
//               turns: null | [qx, qy, qz, qw, ...],  // its turn from frame 0 in each
//               tokens: [[name, value], ...] }],
//     particles: null | { ids: [...], radii: [...], colors: ["#rrggbb" or null, ...],
//                         positions: [[x, y, z, ...] for each frame, null for absent] } }
//
// It draws the walls (moved rigidly: positions interpolated between frames, turns from
// the nearest frame), the particles as instanced spheres (one a frame lacks hidden), their
// trails, and axes; a slider steps through the frames and a play button runs the movie,
// OrbitControls orbit the camera, and hovering a wall shows its parameters. The URL's
// fragment sets the initial time (#t=0.25) or frame (#frame=2, from 0) and can hover a point (#hover=0.5,0.5, as
// fractions of the canvas's width and height), for tests; window.wallsPreview = { ready,
// setTime(t), time(), setFrame(k), frame(), frames, hoverAt(x, y), ... }.
// (A wall's anchor is its origin when it turns, else the centre of its mesh's box.)
//
// Where the browser has no WebGL 2 (which three.js needs), or three.js cannot start it,
// the page shows #no-webgl instead: why, what to do, and the SVG picture(s) that
// walls-preview's SVG writer drew into it (#no-webgl-picture, whose data-frames lists
// the movie's frames it holds, one <g class="frame"> each). The frame shown is the one
// the fragment asks for, or the nearest held; a slider steps through those held.
//
// bundle.sh bundles this file with three.js into ../assets/viewer.bundle.js.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

/** The index k of the frame with times[k] <= t < times[k + 1] and the fraction between. */
function bracket(times, t) {
  const n = times.length;
  if (n <= 1 || t <= times[0]) return [0, 0];
  if (t >= times[n - 1]) return [n - 1, 0];
  let lo = 0;
  let hi = n - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (times[mid] <= t) lo = mid;
    else hi = mid;
  }
  const span = times[hi] - times[lo];
  return [lo, span > 0 ? (t - times[lo]) / span : 0];
}

/** The vector at frame k + f of a flat [x, y, z, ...] array of frames, into out. */
function lerp3(flat, k, f, out) {
  const a = 3 * k;
  const b = flat.length >= a + 6 ? a + 3 : a;
  out.set(
    flat[a] + (flat[b] - flat[a]) * f,
    flat[a + 1] + (flat[b + 1] - flat[a + 1]) * f,
    flat[a + 2] + (flat[b + 2] - flat[a + 2]) * f,
  );
  return out;
}

function element(tag, attributes, parent) {
  const e = document.createElement(tag);
  Object.assign(e, attributes);
  parent.appendChild(e);
  return e;
}

function escapeHtml(s) {
  return String(s).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
}

/** x to four significant figures, as walls_geometry::units::number writes it. */
function number(x) {
  if (x === 0 || !Number.isFinite(x)) return String(x);
  const exponent = Math.floor(Math.log10(Math.abs(x)));
  const trim = (m) => (m.includes('.') ? m.replace(/0+$/, '').replace(/\.$/, '') : m);
  if (exponent >= -3 && exponent < 6) return trim(x.toFixed(Math.max(3 - exponent, 0)));
  const [m, e] = x.toExponential(3).split('e');
  return `${trim(m)}e${e.replace('+', '')}`;
}

/** x (pkdgrav units) as walls_geometry::units::Readout shows it in unit [name, per]. */
function show(x, [name, per], withPkdgrav) {
  const own = name ? `${number(x * per)} ${name}` : number(x * per);
  if (withPkdgrav && !name) return number(x);
  return withPkdgrav ? `${number(x)} (${own})` : own;
}

/** Whether this browser offers WebGL 2, which three.js needs. */
function hasWebgl2() {
  try {
    return !!document.createElement('canvas').getContext('webgl2');
  } catch {
    return false;
  }
}

/** The frame the fragment asks for (#frame=K, else #t=T: the frame nearest T), or null. */
function askedFrame(times) {
  const params = new URLSearchParams(window.location.hash.slice(1));
  if (params.has('frame')) return Math.round(Number(params.get('frame'))) || 0;
  if (!params.has('t')) return null;
  const t = Number(params.get('t'));
  if (!Number.isFinite(t)) return null;
  const [k, f] = bracket(times, t);
  return f < 0.5 ? k : Math.min(k + 1, times.length - 1);
}

/** The page without WebGL: the message with `reason`, and the SVG of the frame asked for. */
function withoutWebgl(data, reason) {
  const times = data.times.length ? data.times : [0];
  const box = document.getElementById('no-webgl');
  box.hidden = false;
  document.getElementById('no-webgl-reason').textContent = reason;
  const picture = document.getElementById('no-webgl-picture');
  const held = (picture.dataset.frames || '0').split(',').map(Number);
  const svg = picture.querySelector('svg');
  const groups = svg ? Array.from(svg.querySelectorAll('g.frame')) : [];
  // The page steps through the frames itself: the SVG's own animation is removed.
  if (svg) svg.querySelectorAll('animate').forEach((a) => a.remove());
  const note = document.getElementById('no-webgl-frame');
  let shown = 0;
  let slider = null;
  function show(j) {
    shown = Math.min(Math.max(Math.round(Number(j)) || 0, 0), Math.max(groups.length - 1, 0));
    groups.forEach((g, i) => g.setAttribute('display', i === shown ? 'inline' : 'none'));
    const k = held[shown] || 0;
    if (slider) slider.value = String(shown);
    note.textContent =
      times.length > 1
        ? `The picture is frame ${k + 1} of ${times.length}` +
          (held.length < times.length ? ` (this page holds the pictures of ${held.length} frames, evenly spaced).` : '.')
        : '';
    document.body.dataset.frame = String(k);
    document.body.dataset.time = String(times[k]);
  }
  /** The held picture nearest frame k. */
  const nearestHeld = (k) => held.reduce((best, h, j) => (Math.abs(h - k) < Math.abs(held[best] - k) ? j : best), 0);
  if (groups.length > 1) {
    const bar = element('div', { id: 'no-webgl-controls' }, box);
    box.insertBefore(bar, picture);
    slider = element('input', { id: 'no-webgl-time', type: 'range', min: '0', max: String(groups.length - 1), step: '1', value: '0' }, bar);
    slider.addEventListener('input', () => show(slider.value));
  }
  const fromHash = () => show(nearestHeld(askedFrame(times) ?? 0));
  window.addEventListener('hashchange', fromHash);
  fromHash();
  window.wallsPreview = {
    ready: true,
    webgl: false,
    frames: times.length,
    setFrame: (k) => show(nearestHeld(Number(k))),
    frame: () => held[shown] || 0,
    time: () => times[held[shown] || 0],
  };
  document.body.dataset.webgl = 'false';
  document.body.dataset.ready = 'true';
}

function main() {
  const data = JSON.parse(document.getElementById('walls-data').textContent);
  if (!hasWebgl2()) {
    withoutWebgl(data, 'this browser offers no WebGL 2 here');
    return;
  }
  const times = data.times.length ? data.times : [0];
  const frameCount = times.length;
  const tStart = times[0];
  const tEnd = times[frameCount - 1];
  const readout = data.readout;

  // The page: the canvas, an info line, the time controls and the tooltip.
  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  } catch (e) {
    withoutWebgl(data, `WebGL could not start: ${e && e.message ? e.message : e}`);
    return;
  }
  document.body.dataset.webgl = 'true';
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setSize(window.innerWidth, window.innerHeight);
  renderer.setClearColor(0x20232a);
  document.body.appendChild(renderer.domElement);

  const info = element('div', { id: 'info' }, document.body);
  const p = data.particles;
  const particleCount = p ? p.ids.length : 0;
  const plural = (n, what) => `${n} ${what}${n === 1 ? '' : 's'}`;
  info.textContent =
    plural(data.walls.length, 'wall') +
    (particleCount ? `, ${plural(particleCount, 'particle')}` : '') +
    (frameCount > 1 ? `, ${plural(frameCount, 'frame')}` : '') +
    ` · scene ${data.sizeLabel} across, axes half that` +
    ' · drag to orbit, right-drag to pan, wheel to zoom, hover a wall for its parameters';
  const bar = element('div', { id: 'controls' }, document.body);
  const play = element('button', { id: 'play', type: 'button', textContent: '▶', title: 'play / pause' }, bar);
  const slider = element('input', { id: 'time', type: 'range', min: '0', max: String(frameCount - 1), step: '1', value: '0' }, bar);
  slider.disabled = frameCount < 2;
  const label = element('span', { id: 'time-label' }, bar);
  const tooltip = element('div', { id: 'tooltip', hidden: true }, document.body);

  // The scene, with z up as in pkdgrav's frames, about 1 across around the origin.
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(45, window.innerWidth / window.innerHeight, 1e-3, 100);
  camera.up.set(0, 0, 1);
  camera.position.set(1.6, -2.2, 1.4).multiplyScalar(0.55);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.minDistance = 0.01;
  controls.maxDistance = 30;
  controls.update();

  scene.add(new THREE.AmbientLight(0xffffff, 1.2));
  const light = new THREE.DirectionalLight(0xffffff, 2.0);
  scene.add(light);
  scene.add(light.target);
  scene.add(new THREE.AxesHelper(0.5));

  // The walls: each the first frame's mesh about its origin, placed in each frame.
  const walls = data.walls.map((w) => {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(w.positions, 3));
    geometry.setIndex(w.indices);
    geometry.computeVertexNormals();
    const material = new THREE.MeshLambertMaterial({
      color: new THREE.Color(w.color),
      side: THREE.DoubleSide,
      transparent: w.opacity < 1,
      opacity: w.opacity,
      depthWrite: w.opacity >= 1,
    });
    const mesh = new THREE.Mesh(geometry, material);
    mesh.userData.wall = w;
    // The wall's outline (edges of one triangle only, and creases over 10°), moving with
    // it, so that a wall the colour of the floor under it still shows.
    const outline = new THREE.LineSegments(
      new THREE.EdgesGeometry(geometry, 10),
      new THREE.LineBasicMaterial({ color: 0x333333, transparent: w.opacity < 1, opacity: w.opacity }),
    );
    outline.raycast = () => {};
    mesh.add(outline);
    scene.add(mesh);
    return mesh;
  });

  // The particles: one instanced sphere each; each frame's positions as floats, NaN
  // where the frame lacks the particle.
  let spheres = null;
  let frames = [];
  const colors = [];
  if (particleCount) {
    frames = p.positions.map((a) => Float32Array.from(a, (x) => (x === null ? NaN : x)));
    // The parsed arrays (a number each, boxed where a frame lacks a particle) are no
    // longer needed: the floats hold the frames in a quarter of the memory or less.
    p.positions = null;
    spheres = new THREE.InstancedMesh(new THREE.SphereGeometry(1, 16, 12), new THREE.MeshLambertMaterial(), particleCount);
    const white = new THREE.Color(0xdddddd);
    for (let i = 0; i < particleCount; i++) {
      colors.push(p.colors[i] ? new THREE.Color(p.colors[i]) : white);
      spheres.setColorAt(i, colors[i]);
    }
    spheres.frustumCulled = false;
    scene.add(spheres);
  }

  // The trails: each particle's path over its last `trails` frames, as line segments.
  const trailLength = particleCount && frameCount > 1 ? Math.max(0, Math.floor(data.trails || 0)) : 0;
  let trails = null;
  if (trailLength) {
    const segments = particleCount * trailLength;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(segments * 6), 3));
    const rgb = new Float32Array(segments * 6);
    for (let i = 0; i < particleCount; i++) {
      for (let v = 0; v < 2 * trailLength; v++) colors[i].toArray(rgb, 3 * (2 * i * trailLength + v));
    }
    geometry.setAttribute('color', new THREE.BufferAttribute(rgb, 3));
    trails = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ vertexColors: true }));
    trails.frustumCulled = false;
    scene.add(trails);
  }

  const render = () => {
    light.position.copy(camera.position);
    light.target.position.copy(controls.target);
    renderer.render(scene, camera);
  };

  // Time.
  let time = tStart;
  let nearest = 0;
  const scratch = new THREE.Vector3();
  const matrix = new THREE.Matrix4();
  const identity = new THREE.Quaternion();
  const scale = new THREE.Vector3();
  const hidden = new THREE.Vector3(0, 0, 0);
  /** Particle i's position at frame k + f into out, or null if it is not drawn then. */
  function particleAt(i, k, f, out) {
    const a = frames[k];
    const b = frames[Math.min(k + 1, frameCount - 1)];
    const j = 3 * i;
    if (!Number.isNaN(a[j]) && !Number.isNaN(b[j])) {
      return out.set(a[j] + (b[j] - a[j]) * f, a[j + 1] + (b[j + 1] - a[j + 1]) * f, a[j + 2] + (b[j + 2] - a[j + 2]) * f);
    }
    const c = f < 0.5 ? a : b;
    return Number.isNaN(c[j]) ? null : out.set(c[j], c[j + 1], c[j + 2]);
  }
  function setTime(t) {
    t = Number(t);
    if (!Number.isFinite(t)) t = tStart;
    time = Math.min(Math.max(t, tStart), tEnd);
    const [k, f] = bracket(times, time);
    nearest = f < 0.5 ? k : Math.min(k + 1, frameCount - 1);
    for (const mesh of walls) {
      const w = mesh.userData.wall;
      lerp3(w.origins, k, f, mesh.position);
      if (w.turns) mesh.quaternion.fromArray(w.turns, 4 * nearest);
    }
    if (spheres) {
      for (let i = 0; i < particleCount; i++) {
        const q = particleAt(i, k, f, scratch);
        const r = q ? p.radii[i] : 0;
        matrix.compose(q || hidden, identity, scale.set(r, r, r));
        spheres.setMatrixAt(i, matrix);
      }
      spheres.instanceMatrix.needsUpdate = true;
    }
    if (trails) {
      // Segments from frame max(0, k − n + 1) to k, then to the time shown; a segment
      // with an end the frames lack is drawn as a point.
      const out = trails.geometry.attributes.position.array;
      const from = new THREE.Vector3();
      const to = new THREE.Vector3();
      for (let i = 0; i < particleCount; i++) {
        let o = 6 * i * trailLength;
        for (let s = 0; s < trailLength; s++, o += 6) {
          const start = k - trailLength + 1 + s;
          const a = start >= 0 ? particleAt(i, start, 0, from) : null;
          const b = a ? (s === trailLength - 1 ? particleAt(i, k, f, to) : particleAt(i, start + 1, 0, to)) : null;
          const e = b || a || hidden;
          (a || e).toArray(out, o);
          e.toArray(out, o + 3);
        }
      }
      trails.geometry.attributes.position.needsUpdate = true;
    }
    slider.value = String(nearest);
    label.textContent = `t = ${show(time, readout.time, readout.withPkdgrav)}`;
    const step = data.steps ? data.steps[nearest] : null;
    label.title = `frame ${nearest + 1} of ${frameCount}` + (step === null || step === undefined ? '' : `, step ${step}`);
    document.body.dataset.time = String(time);
    document.body.dataset.frame = String(nearest);
    render();
  }
  const setFrame = (k) => setTime(times[Math.min(Math.max(Math.round(Number(k)) || 0, 0), frameCount - 1)]);

  // Play: the whole span in ten seconds (at least a tenth of a second a frame), looping.
  const span = tEnd - tStart;
  const duration = Math.max(10, frameCount / 10);
  let playing = false;
  let last = 0;
  function setPlaying(on) {
    playing = on && span > 0;
    play.textContent = playing ? '❚❚' : '▶';
    last = performance.now();
  }
  play.addEventListener('click', () => setPlaying(!playing));
  slider.addEventListener('input', () => {
    setPlaying(false);
    setFrame(slider.value);
  });
  const tick = (now) => {
    if (playing) {
      const t = time + ((now - last) / 1000) * (span / duration);
      last = now;
      setTime(t > tEnd ? tStart : t);
    }
    requestAnimationFrame(tick);
  };
  controls.addEventListener('change', render);

  // Hover: the wall under the pointer, its parameters in the tooltip.
  const raycaster = new THREE.Raycaster();
  const pointer = new THREE.Vector2();
  let hovered = null;
  function hoverAt(x, y) {
    const rect = renderer.domElement.getBoundingClientRect();
    pointer.set(((x - rect.left) / rect.width) * 2 - 1, -((y - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(pointer, camera);
    const hit = raycaster.intersectObjects(walls, false)[0];
    const mesh = hit ? hit.object : null;
    if (hovered !== mesh) {
      if (hovered) hovered.material.emissive.setHex(0x000000);
      if (mesh) mesh.material.emissive.setHex(0x333333);
      hovered = mesh;
      render();
    }
    if (!mesh) {
      tooltip.hidden = true;
      return null;
    }
    const w = mesh.userData.wall;
    tooltip.innerHTML =
      `<b>wall ${w.index}</b> · ${escapeHtml(w.type)}` +
      w.tokens.map(([k, v]) => `<br><span class="key">${escapeHtml(k)}</span> ${escapeHtml(v)}`).join('');
    tooltip.hidden = false;
    tooltip.style.left = `${x + 14}px`;
    tooltip.style.top = `${y + 14}px`;
    return w.index;
  }
  renderer.domElement.addEventListener('pointermove', (e) => hoverAt(e.clientX, e.clientY));
  renderer.domElement.addEventListener('pointerleave', () => {
    tooltip.hidden = true;
  });

  window.addEventListener('resize', () => {
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(window.innerWidth, window.innerHeight);
    render();
  });

  // The fragment: #t=TIME&hover=FX,FY, the point hovered as fractions of the canvas.
  function fromHash() {
    const params = new URLSearchParams(window.location.hash.slice(1));
    if (params.has('frame')) setFrame(params.get('frame'));
    else setTime(params.has('t') ? params.get('t') : time);
    if (params.has('hover')) {
      const [fx, fy] = params.get('hover').split(',').map(Number);
      const rect = renderer.domElement.getBoundingClientRect();
      hoverAt(rect.left + fx * rect.width, rect.top + fy * rect.height);
    }
  }
  window.addEventListener('hashchange', fromHash);

  window.wallsPreview = {
    ready: true,
    tStart,
    tEnd,
    frames: frameCount,
    setTime,
    time: () => time,
    setFrame,
    frame: () => nearest,
    play: () => setPlaying(true),
    pause: () => setPlaying(false),
    hoverAt,
    render,
  };
  fromHash();
  document.body.dataset.ready = 'true';
  requestAnimationFrame(tick);
}

main();
