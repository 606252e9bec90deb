// The page of `lsolid view`: the model in 3D (three.js, Z up, millimetres),
// the build's progress and report, the controls, and the downloads. The
// server tells every change of its status on /events; the skeleton and the
// mesh come as binary from /skeleton and /mesh (encoding.hpp describes
// their layout).
'use strict';
(function () {
  const $ = (id) => document.getElementById(id);
  const canvas = $('canvas');

  // ---- the scene
  const renderer = new THREE.WebGLRenderer({
    canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xf2f2f2);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(35, 1, 1, 100000);
  camera.up.set(0, 0, 1);
  camera.position.set(-220, -300, 220);
  const orbit = new THREE.OrbitControls(camera, canvas);
  orbit.target.set(0, 0, 40);
  orbit.update();
  scene.add(new THREE.HemisphereLight(0xffffff, 0x666666, 0.75));
  const sun = new THREE.DirectionalLight(0xffffff, 0.55);
  sun.position.set(-1, -2, 3);
  scene.add(sun);
  const fill = new THREE.DirectionalLight(0xffffff, 0.2);
  fill.position.set(2, 1, 1);
  scene.add(fill);

  // The bed: a 10 mm grid of the printer's size (`--bed`), centred on the
  // origin where lsolid places the model, and the build volume's edges.
  // three.js frees a geometry's and a material's GPU buffers only when
  // told: every object replaced is disposed of.
  function dispose(object) {
    object.traverse((o) => {
      if (o.geometry) o.geometry.dispose();
      if (o.material) o.material.dispose();
    });
  }
  let bedObject = null;
  let bedSize = '';
  function showBed(size) {
    const [width, depth, height] = size;
    const key = size.join('x');
    if (key === bedSize) return;
    bedSize = key;
    if (bedObject) {
      scene.remove(bedObject);
      dispose(bedObject);
    }
    bedObject = new THREE.Group();
    const x0 = -width / 2;
    const y0 = -depth / 2;
    const grid = [];
    for (let x = 0; x <= width + 1e-9; x += 10) {
      grid.push(x0 + x, y0, 0, x0 + x, y0 + depth, 0);
    }
    for (let y = 0; y <= depth + 1e-9; y += 10) {
      grid.push(x0, y0 + y, 0, x0 + width, y0 + y, 0);
    }
    const lines = new THREE.BufferGeometry();
    lines.setAttribute('position', new THREE.Float32BufferAttribute(grid, 3));
    bedObject.add(new THREE.LineSegments(lines,
      new THREE.LineBasicMaterial({ color: 0xcccccc })));
    const box = new THREE.BoxGeometry(width, depth, height);
    box.translate(0, 0, height / 2);
    bedObject.add(new THREE.LineSegments(new THREE.EdgesGeometry(box),
      new THREE.LineBasicMaterial({ color: 0x999999, transparent: true, opacity: 0.5 })));
    scene.add(bedObject);
    redraw();
  }

  let skeletonObject = null;
  let modelObject = null;
  let fitted = false;

  // Drawn only when something changed: a still model costs no CPU, which
  // the build running beside the page needs.
  let dirty = true;
  const redraw = () => { dirty = true; };
  showBed([220, 220, 250]);
  orbit.addEventListener('change', redraw);
  function resize() {
    const w = canvas.clientWidth;
    const h = canvas.clientHeight;
    if (canvas.width !== Math.floor(w * renderer.getPixelRatio()) ||
        canvas.height !== Math.floor(h * renderer.getPixelRatio())) {
      renderer.setSize(w, h, false);
      camera.aspect = w / Math.max(h, 1);
      camera.updateProjectionMatrix();
      dirty = true;
    }
  }
  function render() {
    resize();
    if (dirty) {
      dirty = false;
      renderer.render(scene, camera);
    }
    requestAnimationFrame(render);
  }
  requestAnimationFrame(render);

  function colorOf(hex) {
    return new THREE.Color(hex || '#7b4a2a');
  }

  // Points the camera at a box of the model, from a three-quarter view.
  function fit(box) {
    const size = new THREE.Vector3();
    box.getSize(size);
    const centre = new THREE.Vector3();
    box.getCenter(centre);
    const radius = Math.max(size.length() / 2, 10);
    const distance = radius / Math.sin((camera.fov * Math.PI) / 360) * 1.15;
    const direction = new THREE.Vector3(-0.55, -0.75, 0.45).normalize();
    camera.position.copy(centre).addScaledVector(direction, distance);
    camera.near = distance / 100;
    camera.far = distance * 100;
    camera.updateProjectionMatrix();
    orbit.target.copy(centre);
    orbit.update();
    redraw();
  }

  // Puts `next` in the scene in place of `old` (disposed of) and returns it;
  // the camera is fitted to the first object that has something to show.
  function replace(old, next, hasSomething) {
    if (old) {
      scene.remove(old);
      dispose(old);
    }
    scene.add(next);
    if (!fitted && hasSomething) {
      fit(new THREE.Box3().setFromObject(next));
      fitted = true;
    }
    return next;
  }

  // ---- the skeleton: segments as lines, polygons as flat leaves
  function showSkeleton(buffer, palette) {
    const view = new DataView(buffer);
    const tag = String.fromCharCode(view.getUint8(0), view.getUint8(1),
      view.getUint8(2), view.getUint8(3));
    if (tag !== 'LSK1') return;
    const segments = view.getUint32(4, true);
    const polygons = view.getUint32(8, true);
    let at = 12;
    const positions = new Float32Array(segments * 6);
    const colors = new Float32Array(segments * 6);
    for (let i = 0; i < segments; ++i) {
      for (let k = 0; k < 6; ++k) {
        positions[i * 6 + k] = view.getFloat32(at + k * 4, true);
      }
      const c = colorOf(palette[view.getUint32(at + 32, true) % palette.length]);
      for (let k = 0; k < 2; ++k) {
        colors[i * 6 + k * 3] = c.r;
        colors[i * 6 + k * 3 + 1] = c.g;
        colors[i * 6 + k * 3 + 2] = c.b;
      }
      at += 36;
    }
    const group = new THREE.Group();
    const lines = new THREE.BufferGeometry();
    lines.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    lines.setAttribute('color', new THREE.BufferAttribute(colors, 3));
    group.add(new THREE.LineSegments(lines,
      new THREE.LineBasicMaterial({ vertexColors: THREE.VertexColors })));
    const leaf = [];
    const leafColors = [];
    for (let i = 0; i < polygons; ++i) {
      const count = view.getUint32(at, true);
      const c = colorOf(palette[view.getUint32(at + 4, true) % palette.length]);
      at += 8;
      const points = [];
      for (let k = 0; k < count; ++k) {
        points.push([view.getFloat32(at, true), view.getFloat32(at + 4, true),
          view.getFloat32(at + 8, true)]);
        at += 12;
      }
      for (let k = 1; k + 1 < points.length; ++k) {
        for (const p of [points[0], points[k], points[k + 1]]) {
          leaf.push(p[0], p[1], p[2]);
          leafColors.push(c.r, c.g, c.b);
        }
      }
    }
    if (leaf.length > 0) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position',
        new THREE.BufferAttribute(new Float32Array(leaf), 3));
      geometry.setAttribute('color',
        new THREE.BufferAttribute(new Float32Array(leafColors), 3));
      geometry.computeVertexNormals();
      group.add(new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({
        vertexColors: THREE.VertexColors, side: THREE.DoubleSide })));
    }
    skeletonObject = replace(skeletonObject, group, segments + polygons > 0);
    applyVisibility();
  }

  // ---- the model: one colour per triangle, overhangs shaded on request
  let lastMesh = null;
  function showMesh(buffer, palette) {
    lastMesh = { buffer, palette };
    const view = new DataView(buffer);
    const tag = String.fromCharCode(view.getUint8(0), view.getUint8(1),
      view.getUint8(2), view.getUint8(3));
    if (tag !== 'LSM1') return;
    const vertices = view.getUint32(4, true);
    const triangles = view.getUint32(8, true);
    const points = new Float32Array(buffer, 12, vertices * 3);
    const corners = new Uint32Array(buffer, 12 + vertices * 12, triangles * 3);
    const colorIndex = new Uint32Array(buffer,
      12 + vertices * 12 + triangles * 12, triangles);
    const overhang = new Uint32Array(buffer,
      12 + vertices * 12 + triangles * 16, triangles);
    const shade = $('show-overhang').checked;
    const positions = new Float32Array(triangles * 9);
    const colors = new Float32Array(triangles * 9);
    const warn = new THREE.Color('#e23a2e');
    const base = palette.map(colorOf);
    const c = new THREE.Color();
    for (let t = 0; t < triangles; ++t) {
      c.copy(base[colorIndex[t] % base.length]);
      if (shade && overhang[t]) c.lerp(warn, 0.75);
      for (let k = 0; k < 3; ++k) {
        const v = corners[t * 3 + k];
        positions[t * 9 + k * 3] = points[v * 3];
        positions[t * 9 + k * 3 + 1] = points[v * 3 + 1];
        positions[t * 9 + k * 3 + 2] = points[v * 3 + 2];
        colors[t * 9 + k * 3] = c.r;
        colors[t * 9 + k * 3 + 1] = c.g;
        colors[t * 9 + k * 3 + 2] = c.b;
      }
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3));
    geometry.computeVertexNormals();
    const mesh = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({
      vertexColors: THREE.VertexColors }));
    // Overhanging faces face down, hidden from the usual view from above:
    // they are drawn again through the model, faintly, so that where the
    // supports go shows from any side.
    let shown = 0;
    if (shade) {
      const through = new Float32Array(triangles * 9);
      for (let t = 0; t < triangles; ++t) {
        if (!overhang[t]) continue;
        through.set(positions.subarray(t * 9, t * 9 + 9), shown * 9);
        ++shown;
      }
      if (shown > 0) {
        const g = new THREE.BufferGeometry();
        g.setAttribute('position',
          new THREE.BufferAttribute(through.slice(0, shown * 9), 3));
        const overlay = new THREE.Mesh(g, new THREE.MeshBasicMaterial({
          color: warn, transparent: true, opacity: 0.3, depthTest: false,
          depthWrite: false, side: THREE.DoubleSide }));
        overlay.name = 'overhang-overlay';
        overlay.renderOrder = 1;
        mesh.add(overlay);
      }
    }
    document.body.dataset.overhangOverlay = String(shown);
    modelObject = replace(modelObject, mesh, triangles > 0);
    applyVisibility();
  }

  // A skeleton newer than the model (the file was saved, a control moved,
  // and the solid is on its way) is shown over the old model, faded.
  let skeletonVersion = 0;
  let modelVersion = 0;
  function applyVisibility() {
    const newer = skeletonObject !== null && skeletonVersion > modelVersion;
    if (skeletonObject) {
      skeletonObject.visible = $('show-skeleton').checked || !modelObject || newer;
    }
    if (modelObject) {
      const m = modelObject.material;
      m.transparent = newer;
      m.opacity = newer ? 0.25 : 1;
      m.depthWrite = !newer;
      m.needsUpdate = true;
    }
    document.body.dataset.faded = newer ? '1' : '0';
    redraw();
  }
  $('show-skeleton').addEventListener('change', applyVisibility);
  $('show-overhang').addEventListener('change', () => {
    if (lastMesh) showMesh(lastMesh.buffer, lastMesh.palette);
  });

  // ---- the report
  function row(list, name, value) {
    const dt = document.createElement('dt');
    dt.textContent = name;
    const dd = document.createElement('dd');
    dd.textContent = value;
    list.append(dt, dd);
  }
  function showReport(report) {
    const verdict = $('verdict');
    const list = $('report');
    list.textContent = '';
    if (!report) {
      verdict.textContent = 'no model yet';
      verdict.className = 'verdict not-printable';
      return;
    }
    verdict.textContent = report.printable ? 'printable' : 'NOT printable';
    verdict.className = 'verdict ' + (report.printable ? 'printable' : 'not-printable');
    const min = report.bounds.min;
    const max = report.bounds.max;
    row(list, 'size', (max[0] - min[0]).toFixed(1) + ' × ' +
      (max[1] - min[1]).toFixed(1) + ' × ' + (max[2] - min[2]).toFixed(1) + ' mm');
    if (report.fits_bed !== null && report.fits_bed !== undefined) {
      row(list, 'bed', report.fits_bed ? 'fits' : 'does NOT fit');
    }
    row(list, 'pieces', String(report.pieces));
    row(list, 'triangles', String(report.triangles));
    row(list, 'volume', (report.volume_mm3 / 1000).toFixed(2) + ' cm³');
    row(list, 'overhang', report.overhang_mm2.toFixed(0) + ' mm²' +
      (report.needs_supports ? ' (supports)' : ''));
    const s = report.seconds;
    row(list, 'time', ['skeleton', 'parts', 'union', 'rounding', 'decimation', 'check']
      .map((k) => k + ' ' + s[k].toFixed(2) + ' s').join(', '));
    if (!report.printable && report.problems) {
      row(list, 'problems', report.problems.join('; '));
    }
    $('warnings').textContent = (report.warnings || []).join(' ');
  }

  // ---- the controls
  let sending = null;
  // The controls the maker changed: only those are sent, so the command
  // line shows what differs from the file.
  const touched = new Set();
  let constantNames = '';
  const constantInputs = {};
  function showConstants(constants, active) {
    const names = constants.map((c) => c.name).join(' ');
    if (names !== constantNames) {
      // The file's constants changed: new sliders for the new set.
      constantNames = names;
      const box = $('constants');
      box.textContent = '';
      for (const name of Object.keys(constantInputs)) delete constantInputs[name];
      for (const c of constants) {
        const label = document.createElement('label');
        label.className = 'constant';
        label.textContent = c.name + ' ';
        const range = document.createElement('input');
        range.type = 'range';
        range.min = c.min;
        range.max = c.max;
        range.step = c.step;
        const number = document.createElement('input');
        number.type = 'number';
        number.step = c.step;
        number.dataset.constant = c.name;
        range.addEventListener('input', () => {
          number.value = range.value;
          touched.add('define:' + c.name);
          schedule();
        });
        number.addEventListener('change', () => {
          range.value = number.value;
          touched.add('define:' + c.name);
          schedule();
        });
        constantInputs[c.name] = { range, number };
        label.append(range, number);
        box.append(label);
      }
    }
    for (const c of constants) {
      const inputs = constantInputs[c.name];
      // A value the file moved out of the slider's range widens it.
      if (c.value < Number(inputs.range.min) || c.value > Number(inputs.range.max)) {
        inputs.range.min = c.min;
        inputs.range.max = c.max;
        inputs.range.step = c.step;
        inputs.number.step = c.step;
      }
      if (inputs.number !== active && inputs.range !== active &&
          !touched.has('define:' + c.name)) {
        inputs.number.value = c.value;
        inputs.range.value = c.value;
      }
    }
  }
  function showControls(controls) {
    if (!controls) return;
    const active = document.activeElement;
    // A value the maker typed stays as typed, even when it was refused
    // (the error names it): only untouched fields follow the build.
    const set = (id, value) => {
      const input = $(id);
      if (input !== active && !touched.has(id) && value !== null &&
          value !== undefined) {
        input.value = value;
      }
    };
    set('n', controls.n);
    set('seed', controls.seed);
    set('size', controls.size_mm);
    set('wall', controls.wall_mm);
    set('tolerance', controls.tolerance_mm);
    set('base', controls.base);
    if (controls.bed_mm) showBed(controls.bed_mm);
    showConstants(controls.constants, active);
  }
  function params() {
    const body = {};
    const take = (id, key, unit) => {
      const v = $(id).value.trim();
      if (!touched.has(id)) return;
      if (v !== '') body[key] = unit ? v + unit : v;
    };
    take('n', 'n');
    take('seed', 'seed');
    take('size', 'size', 'mm');
    take('wall', 'wall', 'mm');
    take('tolerance', 'tolerance', 'mm');
    take('base', 'base');
    body.defines = {};
    for (const [name, inputs] of Object.entries(constantInputs)) {
      if (touched.has('define:' + name) && inputs.number.value !== '') {
        body.defines[name] = inputs.number.value;
      }
    }
    return body;
  }
  function send(body) {
    fetch('/params', { method: 'POST', body: JSON.stringify(body),
      headers: { 'Content-Type': 'application/json' } });
  }
  // A slider moved: built once it rests for a quarter of a second.
  function schedule() {
    clearTimeout(sending);
    sending = setTimeout(() => send(params()), 250);
  }
  // Back to what the file and the command line say.
  $('reset').addEventListener('click', () => {
    clearTimeout(sending);
    touched.clear();
    send({});
  });
  for (const id of ['n', 'seed', 'size', 'wall', 'tolerance', 'base']) {
    $(id).addEventListener('change', () => {
      touched.add(id);
      schedule();
    });
  }
  $('controls').addEventListener('submit', (e) => e.preventDefault());

  // ---- the status, as the server tells it
  let skeletonAsked = 0;
  let modelAsked = 0;
  let applied = 0;
  let palette = ['#7b4a2a'];
  async function fetchBinary(path, version) {
    const response = await fetch(path + '?v=' + version);
    return response.ok ? response.arrayBuffer() : null;
  }
  async function update(status) {
    // The first /status and the events race: an older snapshot than one
    // applied would undo it.
    if (status.version <= applied) return;
    applied = status.version;
    document.body.dataset.version = status.version;
    if (status.controls) {
      palette = status.controls.palette || palette;
      showControls(status.controls);
    }
    $('command').textContent = status.command;
    const building = status.stage !== 'done';
    $('progress').hidden = !building;
    $('stage').textContent = status.stage;
    $('bar-fill').style.width = Math.round(status.fraction * 100) + '%';
    if (building) {
      $('verdict').textContent = 'building…';
      $('verdict').className = 'verdict';
    }
    const error = $('error');
    error.hidden = !status.error;
    error.textContent = status.error ? status.error.text : '';
    // A version replaced while it was fetched is answered 410 Gone and
    // not drawn; the snapshot that replaced it comes next.
    if (status.skeleton && status.skeleton !== skeletonAsked) {
      skeletonAsked = status.skeleton;
      const buffer = await fetchBinary('/skeleton', status.skeleton);
      if (buffer) {
        skeletonVersion = status.skeleton;
        showSkeleton(buffer, palette);
        document.body.dataset.skeleton = status.skeleton;
      }
    }
    if (status.model && status.model !== modelAsked) {
      modelAsked = status.model;
      const buffer = await fetchBinary('/mesh', status.model);
      if (buffer) {
        modelVersion = status.model;
        showMesh(buffer, palette);
        document.body.dataset.model = status.model;
      }
    }
    if (!building) showReport(status.report);
  }
  let queue = Promise.resolve();
  function receive(status) {
    queue = queue.then(() => update(status)).catch((e) => console.error(e));
  }
  const events = new EventSource('/events');
  events.onmessage = (e) => receive(JSON.parse(e.data));
  fetch('/status').then((r) => r.json()).then(receive);
})();
