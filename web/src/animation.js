// The animation page of `tumble run --animate`. The trajectory arrives in
// <script type="application/json" id="tumble-data"> (written by src/tumble/output/animation_html.cpp):
//   name, rows, planar (seen from +z, y up), bodies [{name, extent, parts: [{name, shape, dims..., position, quaternion}]}],
//   planes    [{name, point, normal}]: the contacts' fixed planes (ground, ramps)
//   joints    [{name, type, body, point, axis}]: each joint where it holds its second body (the
//             point from that body's COM and the hinge's or slider's axis, in its axes)
//   rods      [{name, a, end_a, b, end_b}]: each distance joint's massless rod, from its end on
//             body a to its end on body b (each from its body's COM, its axes; body -1: ground,
//             the end a world point)
//   time      base64 Float64 [rows]
//   system    base64 Float64 [rows][4]: KE, PE, E, |L| (about the world origin)
//   body_rows base64 Float32 [rows][bodies][16]: r_G (3), q_WB (x y z w), omega_W (3), omega_B (3),
//             L about the COM, world (3)
// World z is up. Every name from the scenario is shown through textContent, never as HTML.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import uPlot from 'uplot';

const kPerBody = 16;
const kColors = ['#4f7fd9', '#e08a2c', '#3aa66a', '#c9487a', '#7a5bd1', '#2aa3b8', '#9c8a2e'];

function decode(base64, Type) {
  const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
  return new Type(bytes.buffer);
}

const data = JSON.parse(document.getElementById('tumble-data').textContent);
const rows = data.rows;
const time = decode(data.time, Float64Array);
const system = decode(data.system, Float64Array);
const bodyRows = decode(data.body_rows, Float32Array);
const nBodies = data.bodies.length;
const at = (row, body, k) => bodyRows[(row * nBodies + body) * kPerBody + k];

document.title = data.name;
document.getElementById('title').textContent = data.name;
document.getElementById('summary').textContent =
  `${nBodies} ${nBodies === 1 ? 'body' : 'bodies'}, ${rows} rows, t = ${time[0]} to ` +
  `${time[rows - 1]} s`;

// ---- The scene ----------------------------------------------------------------------------
const box = document.getElementById('canvas-box');
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
box.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color('#ffffff');
const camera = new THREE.PerspectiveCamera(45, 1, 0.01, 1e5);
// World z is up; a planar scenario's y (set before the orbit controls, which read it).
if (data.planar) camera.up.set(0, 1, 0); else camera.up.set(0, 0, 1);
const controls = new OrbitControls(camera, renderer.domElement);
scene.add(new THREE.HemisphereLight('#ffffff', '#8890a0', 2.0));
const sun = new THREE.DirectionalLight('#ffffff', 1.6);
sun.position.set(3, -5, 8);
scene.add(sun);

// Three's cylinders and cones stand along y; tumble's shapes have their axis along z.
function alongZ(geometry) {
  return geometry.rotateX(Math.PI / 2);
}

function partGeometry(part, notes, bodyName) {
  const seg = 48;
  switch (part.shape) {
    case 'box':
      return new THREE.BoxGeometry(part.size[0], part.size[1], part.size[2]);
    case 'plate':
      return new THREE.BoxGeometry(part.size[0], part.size[1], 0.002 * Math.max(...part.size));
    case 'cylinder':
      return alongZ(new THREE.CylinderGeometry(part.radius, part.radius, part.length, seg));
    case 'capsule':
      return alongZ(new THREE.CapsuleGeometry(part.radius, part.length, seg / 4, seg));
    case 'disk':
      return alongZ(new THREE.CylinderGeometry(part.radius, part.radius, 0.01 * part.radius, seg));
    case 'tube': {
      const ri = part.inner_radius, ro = part.outer_radius, h = part.length / 2;
      const profile = [[ri, -h], [ro, -h], [ro, h], [ri, h], [ri, -h]].map(
        ([x, y]) => new THREE.Vector2(x, y));
      return alongZ(new THREE.LatheGeometry(profile, seg));
    }
    case 'ring':
      return new THREE.TorusGeometry(part.radius, 0.03 * part.radius, 12, seg);
    case 'torus':
      return new THREE.TorusGeometry(part.radius, part.tube_radius, Math.max(12, seg / 2), seg);
    case 'rod':
      return new THREE.CylinderGeometry(0.01 * part.length, 0.01 * part.length, part.length, 12)
        .rotateZ(Math.PI / 2);
    case 'sphere':
    case 'shell':
      return new THREE.SphereGeometry(part.radius, seg, seg / 2);
    case 'cone':
      // Base at z = -h/4, apex at z = 3h/4: the frame sits at the COM.
      return alongZ(new THREE.ConeGeometry(part.radius, part.height, seg)).translate(
        0, 0, part.height / 4);
    case 'mesh':
      if (part.vertices) {
        const g = new THREE.BufferGeometry();
        g.setAttribute('position', new THREE.BufferAttribute(decode(part.vertices, Float32Array), 3));
        g.setIndex(new THREE.BufferAttribute(decode(part.triangles, Uint32Array), 1));
        g.computeVertexNormals();
        return g;
      }
      notes.push(`${bodyName}: ${part.name} is drawn as its bounding box (${part.note ?? ''})`);
      return new THREE.BoxGeometry(part.size[0], part.size[1], part.size[2])
        .translate(part.centre[0], part.centre[1], part.centre[2]);
    default:  // a point mass
      return new THREE.SphereGeometry(part.radius, 16, 8);
  }
}

const notes = [];
const bodies = data.bodies.map((spec, b) => {
  const color = kColors[b % kColors.length];
  const group = new THREE.Group();
  const material = new THREE.MeshStandardMaterial({
    color, roughness: 0.6, metalness: 0.05, side: THREE.DoubleSide,
    transparent: false, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
  });
  const shellMaterial = material.clone();
  Object.assign(shellMaterial, {transparent: true, opacity: 0.3, depthWrite: false});
  // Edges a shade darker than the body, so a composite reads as one body of its colour; thin
  // parts (a rod, a ring, a point) are all edge and get none.
  const edgeMaterial = new THREE.LineBasicMaterial({
    color: new THREE.Color(color).multiplyScalar(0.55),
  });
  for (const part of spec.parts) {
    const geometry = partGeometry(part, notes, spec.name);
    // A shell is drawn see-through: what moves inside it (a ball in a bowl) stays in view.
    const mesh = new THREE.Mesh(geometry, part.shape === 'shell' ? shellMaterial : material);
    const holder = new THREE.Group();
    holder.add(mesh);
    if (!['rod', 'ring', 'point'].includes(part.shape)) {
      holder.add(new THREE.LineSegments(new THREE.EdgesGeometry(geometry, 25), edgeMaterial));
    }
    holder.position.fromArray(part.position);
    holder.quaternion.fromArray(part.quaternion);
    group.add(holder);
  }
  const axes = new THREE.AxesHelper(1.25 * spec.extent);
  axes.material.depthTest = false;
  axes.renderOrder = 2;
  group.add(axes);
  scene.add(group);

  const arrow = (c) => {
    const a = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 1, c);
    a.line.material.depthTest = false;
    a.cone.material.depthTest = false;
    a.renderOrder = 3;
    scene.add(a);
    return a;
  };
  // Arrow lengths: the largest magnitude over the run is drawn 1.6 body extents long.
  let maxW = 0, maxL = 0;
  for (let i = 0; i < rows; ++i) {
    maxW = Math.max(maxW, Math.hypot(at(i, b, 7), at(i, b, 8), at(i, b, 9)));
    maxL = Math.max(maxL, Math.hypot(at(i, b, 13), at(i, b, 14), at(i, b, 15)));
  }
  const trailPositions = new Float32Array(rows * 3);
  for (let i = 0; i < rows; ++i) {
    for (let k = 0; k < 3; ++k) trailPositions[3 * i + k] = at(i, b, k);
  }
  const trailGeometry = new THREE.BufferGeometry();
  trailGeometry.setAttribute('position', new THREE.BufferAttribute(trailPositions, 3));
  const trail = new THREE.Line(trailGeometry, new THREE.LineBasicMaterial({ color }));
  trail.frustumCulled = false;
  scene.add(trail);
  return {
    spec, color, group, trail, omega: arrow('#cc8800'), momentum: arrow('#aa33cc'),
    omegaScale: maxW > 0 ? 1.6 * spec.extent / maxW : 0,
    momentumScale: maxL > 0 ? 1.6 * spec.extent / maxL : 0,
  };
});

// Joints ride with the body they hold (the joint point is fixed in its frame): a dark pivot, a
// hinge's axle or a slider's rail along the axis, and the link to the COM when the point lies
// outside the body (a point mass on a massless link).
const jointMaterial = new THREE.MeshStandardMaterial({ color: '#3a3f4a', roughness: 0.5 });
const linkMaterial = new THREE.LineBasicMaterial({ color: '#3a3f4a' });
const joints = (data.joints ?? []).map((spec) => {
  const body = bodies[spec.body];
  const point = new THREE.Vector3().fromArray(spec.point);
  const axis = new THREE.Vector3().fromArray(spec.axis).normalize();
  const r = 0.06 * Math.max(body.spec.extent, 0.3 * point.length());
  const holder = new THREE.Group();
  holder.position.copy(point);
  holder.add(new THREE.Mesh(new THREE.SphereGeometry(r, 16, 8), jointMaterial));
  // An axle along the axis the body turns about (a universal joint's: its own, the second) or
  // slides along (a slider's, a cylindrical joint's: longer).
  if (['hinge', 'prismatic', 'cylindrical', 'universal'].includes(spec.type)) {
    const slides = spec.type === 'prismatic' || spec.type === 'cylindrical';
    const length = slides ? 12 * r : 5 * r;
    const rod = new THREE.Mesh(
      new THREE.CylinderGeometry(0.35 * r, 0.35 * r, length, 16), jointMaterial);
    rod.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), axis);  // three's along y
    holder.add(rod);
  }
  body.group.add(holder);
  if (point.length() > 0.9 * body.spec.extent) {
    const link = new THREE.BufferGeometry().setFromPoints([point, new THREE.Vector3()]);
    body.group.add(new THREE.Line(link, linkMaterial));
  }
  return holder;
});

// A rod (a distance joint) is a line between its ends, each riding with its body (or fixed).
const rods = (data.rods ?? []).map((spec) => {
  const ends = [new THREE.Vector3().fromArray(spec.end_a), new THREE.Vector3().fromArray(spec.end_b)];
  const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints(ends), linkMaterial);
  line.frustumCulled = false;  // its ends move every frame
  scene.add(line);
  return { line, ends: [[spec.a, ends[0].clone()], [spec.b, ends[1].clone()]] };
});
const rodEnd = new THREE.Vector3();

// The ground grid lies under everything the bodies reach, at z = 0 unless they go lower.
let lo = new THREE.Vector3(Infinity, Infinity, Infinity);
let hi = new THREE.Vector3(-Infinity, -Infinity, -Infinity);
let zGround = 0;
data.bodies.forEach((spec, b) => {
  for (let i = 0; i < rows; ++i) {
    const p = new THREE.Vector3(at(i, b, 0), at(i, b, 1), at(i, b, 2));
    lo.min(p.clone().subScalar(spec.extent));
    hi.max(p.clone().addScalar(spec.extent));
  }
  zGround = Math.min(zGround, lo.z);
});
const span = Math.max(hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-3);
const gridSize = Math.pow(10, Math.ceil(Math.log10(1.5 * span)));
const grid = new THREE.GridHelper(gridSize, 20, '#9aa3b5', '#d5d9e2');
grid.rotateX(Math.PI / 2);
const centre = lo.clone().add(hi).multiplyScalar(0.5);
grid.position.set(centre.x, centre.y, zGround);
scene.add(grid);

// Each contact's plane: a translucent square with a grid, 1.5 spans wide, about the point of
// the plane nearest the middle of the motion (a ramp shows its slope under the bodies on it).
const planes = (data.planes ?? []).map((spec) => {
  const normal = new THREE.Vector3().fromArray(spec.normal).normalize();
  const point = new THREE.Vector3().fromArray(spec.point);
  const size = 1.5 * span;
  const group = new THREE.Group();
  const fill = new THREE.Mesh(new THREE.PlaneGeometry(size, size),
    new THREE.MeshStandardMaterial({
      color: '#b8c0cf', roughness: 0.9, transparent: true, opacity: 0.45, side: THREE.DoubleSide,
      depthWrite: false, polygonOffset: true, polygonOffsetFactor: 2, polygonOffsetUnits: 2,
    }));
  const lines = new THREE.GridHelper(size, 10, '#7d879a', '#a3acbc');
  lines.rotateX(Math.PI / 2);  // the helper lies in x-z; the square in x-y
  group.add(fill, lines);
  group.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), normal);
  group.position.copy(centre).addScaledVector(normal, -centre.clone().sub(point).dot(normal));
  scene.add(group);
  return group;
});
controls.target.copy(centre);
if (data.planar) {
  // A planar scenario is seen as the chapter draws it: from +z, y up.
  camera.position.copy(centre).add(new THREE.Vector3(0, 0, 2.2).multiplyScalar(span));
} else {
  camera.position.copy(centre).add(new THREE.Vector3(1.2, -1.6, 0.9).multiplyScalar(span));
}
controls.update();

const legend = document.getElementById('legend');
const follow = document.getElementById('follow');
bodies.forEach((body, b) => {
  const li = document.createElement('li');
  li.textContent = body.spec.name;
  li.style.setProperty('--c', body.color);
  legend.appendChild(li);
  const option = document.createElement('option');
  option.value = String(b);
  option.textContent = `follow ${body.spec.name}`;
  follow.appendChild(option);
});
document.getElementById('notes').textContent = notes.join('; ');

function resize() {
  const w = box.clientWidth, h = box.clientHeight;
  renderer.setSize(w, h);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', resize);
resize();

// ---- The plots ----------------------------------------------------------------------------
const plotsBox = document.getElementById('plots');
const axisNames = ['x', 'y', 'z'];
const seriesColors = ['#d33', '#2a2', '#24d'];
// One body: x, y, z in red, green, blue. Several: each body in its colour (the legend's above
// the view), x solid, y dashed, z dotted, and each series' label names its body.
const axisDashes = [undefined, [7, 4], [2, 3]];
function bodySeries(offset, symbol) {
  const series = [{}], columns = [time];
  bodies.forEach((body, b) => {
    for (let k = 0; k < 3; ++k) {
      const column = new Float64Array(rows);
      for (let i = 0; i < rows; ++i) column[i] = at(i, b, offset + k);
      columns.push(column);
      series.push(nBodies === 1
        ? { label: `${symbol}${axisNames[k]}`, stroke: seriesColors[k], width: 1.5 }
        : {
          label: `${body.spec.name} ${symbol}${axisNames[k]}`,
          stroke: body.color, width: 1.5, dash: axisDashes[k],
        });
    }
  });
  return { series, columns };
}
function systemColumn(k) {
  const column = new Float64Array(rows);
  for (let i = 0; i < rows; ++i) column[i] = system[4 * i + k];
  return column;
}
const plotSpecs = [
  { title: 'angular velocity, body axes (rad/s)', ...bodySeries(10, 'ω_B ') },
  { title: 'angular velocity, world axes (rad/s)', ...bodySeries(7, 'ω_W ') },
  {
    title: 'energy (J)',
    series: [{}, { label: 'KE', stroke: '#d33', width: 1.5 }, { label: 'PE', stroke: '#2a2', width: 1.5 },
      { label: 'E', stroke: '#24d', width: 2 }],
    columns: [time, systemColumn(0), systemColumn(1), systemColumn(2)],
  },
  {
    title: '|L| about the world origin (kg m²/s)',
    series: [{}, { label: '|L|', stroke: '#a3c', width: 2 }],
    columns: [time, systemColumn(3)],
  },
];
// The scenario's own plots (output.plots; by default each body's speed and the joints' angles):
// their columns' values row by row, each plot's columns in turn.
const chosenPlots = data.plots ?? [];
const chosenColumns = chosenPlots.reduce((n, plot) => n + plot.columns.length, 0);
const chosenValues = chosenColumns > 0 ? decode(data.plot_values, Float64Array) : new Float64Array(0);
{
  let first = 0;
  for (const plot of chosenPlots) {
    const series = [{}], columns = [time];
    plot.columns.forEach((name, k) => {
      const column = new Float64Array(rows);
      for (let i = 0; i < rows; ++i) column[i] = chosenValues[i * chosenColumns + first + k];
      columns.push(column);
      series.push({ label: name, stroke: kColors[k % kColors.length], width: 1.5 });
    });
    first += plot.columns.length;
    plotSpecs.push({ title: plot.title, series, columns });
  }
}
// The run's events (contacts', jumps, the scenario's), marked on every plot's time axis.
const events = data.events ?? [];
// Tick labels with the digits their spacing needs: ticks 5e-4 apart on |L| = 0.1125 read
// 0.1120 0.1125 0.1130, not 0.112 0.113 0.113.
function tickLabels(_plot, splits) {
  const step = splits.length > 1 ? Math.abs(splits[1] - splits[0]) : 0;
  const largest = Math.max(...splits.map((v) => Math.abs(v)));
  if (!(step > 0) || !Number.isFinite(largest)) return splits.map((v) => String(v));
  if (largest >= 1e6 || largest < 1e-3) {
    const digits = Math.min(15, Math.max(1, Math.ceil(Math.log10(largest / step))));
    return splits.map((v) => (v === 0 ? '0' : v.toExponential(digits)));
  }
  const decimals = Math.min(15, Math.max(0, Math.ceil(-Math.log10(step) - 1e-9)));
  return splits.map((v) => v.toFixed(decimals));
}
// A dashed line across a plot at each event's time.
function markEvents(plot) {
  const { ctx } = plot;
  const top = plot.bbox.top, height = plot.bbox.height;
  ctx.save();
  ctx.strokeStyle = '#888';
  ctx.lineWidth = 1;
  ctx.setLineDash([4, 3]);
  let drawn = 0;
  for (const event of events) {
    const x = Math.round(plot.valToPos(event.t, 'x', true)) + 0.5;
    if (x < plot.bbox.left || x > plot.bbox.left + plot.bbox.width) continue;
    ctx.beginPath();
    ctx.moveTo(x, top);
    ctx.lineTo(x, top + height);
    ctx.stroke();
    ++drawn;
  }
  ctx.restore();
  plot.eventMarks = drawn;
}
// A y range never narrower than a thousandth of the values' size: a conserved quantity that
// wobbles at round-off (1e-12 relative) must read as the flat line it is, not as noise blown up
// to fill the panel.
function conservedAwareRange(_plot, min, max) {
  const floor = 1e-3 * Math.max(Math.abs(min), Math.abs(max), 1e-300);
  const pad = Math.max(0.05 * (max - min), floor);
  return [min - pad, max + pad];
}
const plots = plotSpecs.map((spec) => {
  const holder = document.createElement('div');
  holder.className = 'plot';
  plotsBox.appendChild(holder);
  const plot = new uPlot({
    title: spec.title,
    width: Math.max(340, plotsBox.clientWidth - 4),
    height: 190,
    series: spec.series.map((s, i) => (i === 0 ? { label: 't (s)' } : s)),
    scales: { x: { time: false }, y: { range: conservedAwareRange } },
    axes: [{ label: 't (s)' }, { size: 70, values: tickLabels }],
    cursor: { drag: { x: true, y: false } },
    hooks: { draw: [markEvents] },
  }, spec.columns, holder);
  const cursor = document.createElement('div');
  cursor.className = 'plot-cursor';
  plot.over.appendChild(cursor);
  return { plot, cursor };
});
window.addEventListener('resize', () => {
  for (const { plot } of plots) plot.setSize({ width: Math.max(340, plotsBox.clientWidth - 4), height: 190 });
});

// ---- Playback -----------------------------------------------------------------------------
const slider = document.getElementById('slider');
const playButton = document.getElementById('play');
const timeLabel = document.getElementById('time');
const speedSelect = document.getElementById('speed');
const loopBox = document.getElementById('loop');
const trailBox = document.getElementById('trail');
const vectorsBox = document.getElementById('vectors');
slider.max = String(rows - 1);
slider.step = 'any';

const t0 = time[0], tEnd = time[rows - 1];
let simTime = t0;
let playing = true;
let lastFrame = null;
// Video mode (see videoMode below): the playback clock stops for good and only seek draws.
let video = false;
const videoTime = document.getElementById('video-time');

// The last row with time <= t.
// The work of the last frame, for the browser test (which counts it rather than timing it): the
// rows' times the search read, and the rows whose states it drew from.
const frameWork = { timesRead: 0, rowsDrawn: 0 };

function rowAt(t) {
  let a = 0, b = rows - 1;
  frameWork.timesRead = 1;
  if (t >= time[b]) return b;
  while (b - a > 1) {
    const m = (a + b) >> 1;
    ++frameWork.timesRead;
    if (time[m] <= t) a = m; else b = m;
  }
  return a;
}

const qa = new THREE.Quaternion(), qb = new THREE.Quaternion();
const pa = new THREE.Vector3(), pb = new THREE.Vector3(), v = new THREE.Vector3();
const followOffset = new THREE.Vector3();
function show(t) {
  const i = rowAt(t);
  const j = Math.min(i + 1, rows - 1);
  frameWork.rowsDrawn = j > i ? 2 : 1;
  const s = j > i ? Math.min(1, Math.max(0, (t - time[i]) / (time[j] - time[i]))) : 0;
  const followed = Number(follow.value);
  bodies.forEach((body, b) => {
    const previous = body.group.position.clone();
    pa.set(at(i, b, 0), at(i, b, 1), at(i, b, 2));
    pb.set(at(j, b, 0), at(j, b, 1), at(j, b, 2));
    body.group.position.lerpVectors(pa, pb, s);
    qa.set(at(i, b, 3), at(i, b, 4), at(i, b, 5), at(i, b, 6));
    qb.set(at(j, b, 3), at(j, b, 4), at(j, b, 5), at(j, b, 6));
    body.group.quaternion.slerpQuaternions(qa, qb, s);
    const row = s < 0.5 ? i : j;
    for (const [arrow, offset, scale] of [[body.omega, 7, body.omegaScale], [body.momentum, 13, body.momentumScale]]) {
      v.set(at(row, b, offset), at(row, b, offset + 1), at(row, b, offset + 2));
      const length = v.length() * scale;
      arrow.visible = vectorsBox.checked && length > 1e-9;
      if (arrow.visible) {
        arrow.position.copy(body.group.position);
        arrow.setDirection(v.normalize());
        arrow.setLength(length, Math.min(0.25 * length, 0.3 * body.spec.extent), Math.min(0.12 * length, 0.15 * body.spec.extent));
      }
    }
    body.trail.visible = trailBox.checked;
    body.trail.geometry.setDrawRange(0, i + 1);
    if (b === followed) {
      followOffset.subVectors(body.group.position, previous);
      camera.position.add(followOffset);
      controls.target.copy(body.group.position);
    }
  });
  for (const rod of rods) {
    const positions = rod.line.geometry.attributes.position;
    rod.ends.forEach(([b, end], k) => {
      rodEnd.copy(end);
      if (b >= 0) rodEnd.applyQuaternion(bodies[b].group.quaternion).add(bodies[b].group.position);
      positions.setXYZ(k, rodEnd.x, rodEnd.y, rodEnd.z);
    });
    positions.needsUpdate = true;
  }
  timeLabel.textContent = `t = ${t.toFixed(3)} s`;
  if (video) videoTime.textContent = `t = ${t.toFixed(3)} s`;
  for (const { plot, cursor } of plots) {
    cursor.style.left = `${plot.valToPos(t, 'x')}px`;
  }
}

function draw(t) {
  show(t);
  controls.update();
  renderer.render(scene, camera);
}

function frame(now) {
  if (video) return;  // frames of a video are drawn by seek alone, at the times it asks for
  if (playing && lastFrame !== null) {
    simTime += ((now - lastFrame) / 1000) * Number(speedSelect.value);
    if (simTime > tEnd) {
      if (loopBox.checked) simTime = t0 + ((simTime - t0) % Math.max(tEnd - t0, 1e-12));
      else { simTime = tEnd; setPlaying(false); }
    }
    slider.value = String(rowAt(simTime));
  }
  lastFrame = now;
  draw(simTime);
  requestAnimationFrame(frame);
}

function setPlaying(on) {
  playing = on;
  playButton.textContent = on ? 'Pause' : 'Play';
  if (on && simTime >= tEnd && !loopBox.checked) simTime = t0;
}
playButton.addEventListener('click', () => setPlaying(!playing));
slider.addEventListener('input', () => {
  setPlaying(false);
  simTime = time[Math.round(Number(slider.value))];
});
follow.addEventListener('change', () => {
  const b = Number(follow.value);
  if (b >= 0) {
    // Keep the view direction, centred on the body.
    const offset = camera.position.clone().sub(controls.target);
    controls.target.copy(bodies[b].group.position);
    camera.position.copy(controls.target).add(offset);
  }
});

// One frame of a video (`tumble run --video`, web/render_video.mjs): the 3D view alone fills the
// viewport at one canvas pixel per CSS pixel, with the scenario's name and the time over it, and
// the playback clock stops, so that each frame shows exactly the time seek was given. There is
// no way back: the page is opened for the video only.
function enterVideoMode() {
  setPlaying(false);
  video = true;
  document.body.classList.add('video');
  document.getElementById('video-title').textContent = data.name;
  document.getElementById('video-overlay').hidden = false;
  renderer.setPixelRatio(1);
  resize();
  draw(simTime);
}

// For the browser test and for scripting: read-only views and a way to seek.
window.tumble = {
  rows,
  planes: planes.length,
  joints: joints.length,
  // Each rod's two ends as drawn now, world: [x1, y1, z1, x2, y2, z2].
  rodEnds: () => rods.map((rod) => Array.from(rod.line.geometry.attributes.position.array)),
  planar: Boolean(data.planar),
  // Where the camera looks from, relative to what it looks at, and which way is up in the view.
  view: () => ({
    from: camera.position.clone().sub(controls.target).normalize().toArray(),
    up: camera.up.toArray(),
  }),
  // The body-axes omega plot's series: label and colour, and the legend's colours, for the test.
  seriesStrokes: () => plotSpecs[0].series.slice(1).map((x) => ({ label: x.label, stroke: x.stroke })),
  bodyColors: bodies.map((body) => body.color),
  start: t0,
  end: tEnd,
  get time() { return simTime; },
  get playing() { return playing; },
  get video() { return video; },
  plotPoints: () => plots.map(({ plot }) => plot.data[0].length),
  // Each plot's title, its series' labels, the event marks drawn on it and its y ticks' labels.
  plotDetails: () => plots.map(({ plot }, i) => ({
    title: plotSpecs[i].title,
    labels: plotSpecs[i].series.slice(1).map((x) => x.label),
    eventMarks: plot.eventMarks ?? 0,
    ticks: (plot.axes[1]._values ?? []).map(String),
    values: plot.data.slice(1).map((column) => [column[0], column[column.length - 1]]),
  })),
  events: events.length,
  // The last frame's work: rows' times searched, rows drawn from, and the renderer's draw calls
  // and triangles (three.js resets these each render).
  frameWork: () => ({ ...frameWork, drawCalls: renderer.info.render.calls,
    triangles: renderer.info.render.triangles }),
  seek(t) { setPlaying(false); simTime = t; slider.value = String(rowAt(t)); show(t); renderer.render(scene, camera); },
  play() { if (!video) setPlaying(true); },
  pause() { setPlaying(false); },
  videoMode: enterVideoMode,
};
requestAnimationFrame(frame);
