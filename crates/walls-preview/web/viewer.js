// The viewer of walls-preview's interactive page (crates/walls-preview/src/html.rs).
//
// The page holds the scene as JSON in <script id="walls-data" type="application/json">:
//
//   { tEnd, times: [t0, t1, ...],            // the walls' frames over [0, tEnd]
//     centre: [x, y, z], size,               // the box around the walls
//     walls: [{ index, type, color: "#rrggbb", opacity,
//               positions: [x, y, z, ...],   // the mesh at t = 0
//               indices: [a, b, c, ...],     // its triangles
//               offsets: [dx, dy, dz, ...],  // origin(t_k) − origin(0) for each frame k
//               tokens: [[name, value], ...] }],
//     particles: null | { radii: [...], colors: ["#rrggbb" or null, ...],
//                         times: [...], positions: [[x, y, z, ...] for each frame] } }
//
// It draws the walls (moved rigidly by their offsets, interpolated between frames), the
// particles as instanced spheres, and axes; a slider and a play button set the time,
// OrbitControls orbit the camera, and hovering a wall shows its parameters. The URL's
// fragment sets the initial time (#t=0.25) and can hover a point (#hover=0.5,0.5, as
// fractions of the canvas's width and height), for
// tests; window.wallsPreview = { ready, setTime(t), time(), hoverAt(x, y), ... }.
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

function main() {
  const data = JSON.parse(document.getElementById('walls-data').textContent);
  const tEnd = data.tEnd;
  const size = data.size > 0 ? data.size : 1;
  const centre = new THREE.Vector3(...data.centre);

  // The page: the canvas, an info line, the time controls and the tooltip.
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setSize(window.innerWidth, window.innerHeight);
  renderer.setClearColor(0x20232a);
  document.body.appendChild(renderer.domElement);

  const info = element('div', { id: 'info' }, document.body);
  const particleCount = data.particles ? data.particles.radii.length : 0;
  info.textContent =
    `${data.walls.length} wall${data.walls.length === 1 ? '' : 's'}` +
    (particleCount ? `, ${particleCount} particle${particleCount === 1 ? '' : 's'}` : '') +
    ' · drag to orbit, right-drag to pan, wheel to zoom, hover a wall for its parameters';
  const bar = element('div', { id: 'controls' }, document.body);
  const play = element('button', { id: 'play', type: 'button', textContent: '▶', title: 'play / pause' }, bar);
  const slider = element('input', { id: 'time', type: 'range', min: '0', max: String(tEnd), step: 'any', value: '0' }, bar);
  slider.disabled = !(tEnd > 0);
  const label = element('span', { id: 'time-label' }, bar);
  const tooltip = element('div', { id: 'tooltip', hidden: true }, document.body);

  // The scene, with z up as in pkdgrav's frames.
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(45, window.innerWidth / window.innerHeight, size * 1e-3, size * 100);
  camera.up.set(0, 0, 1);
  camera.position.copy(centre).add(new THREE.Vector3(1.6, -2.2, 1.4).multiplyScalar(size * 0.55));
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(centre);
  controls.update();

  scene.add(new THREE.AmbientLight(0xffffff, 1.2));
  const light = new THREE.DirectionalLight(0xffffff, 2.0);
  scene.add(light);
  scene.add(light.target);
  const axes = new THREE.AxesHelper(size * 0.5);
  scene.add(axes);

  // The walls: each a mesh at t = 0, moved by its offset.
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

  // The particles: one instanced sphere each.
  let spheres = null;
  if (particleCount) {
    const p = data.particles;
    spheres = new THREE.InstancedMesh(new THREE.SphereGeometry(1, 16, 12), new THREE.MeshLambertMaterial(), particleCount);
    const white = new THREE.Color(0xdddddd);
    p.colors.forEach((c, i) => spheres.setColorAt(i, c ? new THREE.Color(c) : white));
    for (let i = p.colors.length; i < particleCount; i++) spheres.setColorAt(i, white);
    spheres.frustumCulled = false;
    scene.add(spheres);
  }

  const render = () => {
    light.position.copy(camera.position);
    light.target.position.copy(controls.target);
    renderer.render(scene, camera);
  };

  // Time.
  let time = 0;
  const scratch = new THREE.Vector3();
  const matrix = new THREE.Matrix4();
  const identity = new THREE.Quaternion();
  const scale = new THREE.Vector3();
  function setTime(t) {
    t = Number(t);
    if (!Number.isFinite(t)) t = 0;
    time = Math.min(Math.max(t, 0), Math.max(tEnd, 0));
    const [k, f] = bracket(data.times, time);
    for (const mesh of walls) lerp3(mesh.userData.wall.offsets, k, f, mesh.position);
    if (spheres) {
      const p = data.particles;
      const [j, g] = bracket(p.times, time);
      const a = p.positions[j];
      const b = p.positions[Math.min(j + 1, p.positions.length - 1)];
      for (let i = 0; i < particleCount; i++) {
        const r = p.radii[i];
        scratch.set(
          a[3 * i] + (b[3 * i] - a[3 * i]) * g,
          a[3 * i + 1] + (b[3 * i + 1] - a[3 * i + 1]) * g,
          a[3 * i + 2] + (b[3 * i + 2] - a[3 * i + 2]) * g,
        );
        matrix.compose(scratch, identity, scale.set(r, r, r));
        spheres.setMatrixAt(i, matrix);
      }
      spheres.instanceMatrix.needsUpdate = true;
    }
    slider.value = String(time);
    label.textContent = `t = ${time.toPrecision(4)} / ${tEnd.toPrecision(4)}`;
    document.body.dataset.time = String(time);
    render();
  }

  // Play: the whole span in ten seconds, looping.
  let playing = false;
  let last = 0;
  function setPlaying(on) {
    playing = on && tEnd > 0;
    play.textContent = playing ? '❚❚' : '▶';
    last = performance.now();
  }
  play.addEventListener('click', () => setPlaying(!playing));
  slider.addEventListener('input', () => {
    setPlaying(false);
    setTime(slider.value);
  });
  const tick = (now) => {
    if (playing) {
      const t = time + ((now - last) / 1000) * (tEnd / 10);
      last = now;
      setTime(t > tEnd ? 0 : t);
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
    setTime(params.has('t') ? params.get('t') : time);
    if (params.has('hover')) {
      const [fx, fy] = params.get('hover').split(',').map(Number);
      const rect = renderer.domElement.getBoundingClientRect();
      hoverAt(rect.left + fx * rect.width, rect.top + fy * rect.height);
    }
  }
  window.addEventListener('hashchange', fromHash);

  window.wallsPreview = {
    ready: true,
    tEnd,
    setTime,
    time: () => time,
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
