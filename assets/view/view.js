// adair's 3D view: the arm, its cell and the run on a timeline.
// Coordinates are the robot's base frame in mm, z up, as adair prints them.
// The page is a replay (the scene and the support points are in the page)
// or live (they come from the adair process as Server-Sent Events).
"use strict";
(function () {
  const T = window.THREE;
  const live = window.ADAIR_MODE === "live";
  const $ = (id) => document.getElementById(id);

  // ---------------------------------------------------------------- data
  // rows: [t, j1..j5 (deg), x, y, z (mm), grip (mm)], as --record writes.
  let scene = null;
  const rows = [];
  let events = 0;

  function parseRows(text) {
    for (const line of text.split("\n")) {
      // The header: `t_s,j1_deg,...`, or `t,j1,...` from before units.
      if (line === "" || /^t[,_]/.test(line)) continue;
      rows.push(line.split(",").map(Number));
    }
  }

  // ------------------------------------------------------------ renderer
  const host = $("view");
  const renderer = new T.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  host.appendChild(renderer.domElement);
  const world = new T.Scene();
  world.background = new T.Color(0xf4f4f0);
  const camera = new T.PerspectiveCamera(40, 1, 5, 50000);
  camera.up.set(0, 0, 1);
  world.add(new T.HemisphereLight(0xffffff, 0x667788, 1.6));
  const sun = new T.DirectionalLight(0xffffff, 1.8);
  sun.position.set(1500, -1000, 2500);
  world.add(sun);

  // Floor grid: 100 mm squares over 2 m, lines every metre darker.
  const grid = new T.GridHelper(2000, 20, 0x888888, 0xcccccc);
  grid.rotation.x = Math.PI / 2;
  world.add(grid);
  // The base frame's axes: x red, y green, z blue, 200 mm.
  const axes = new T.AxesHelper(200);
  axes.position.z = 1;
  world.add(axes);

  // ----------------------------------------------------------------- arm
  const mat = (c, o) => new T.MeshStandardMaterial(Object.assign({ color: c, roughness: 0.6, metalness: 0.1 }, o || {}));
  const ORANGE = mat(0xe8822a), GREY = mat(0x555a60), LIGHT = mat(0xd8d8d8);
  // A cylinder along z from 0 to h (or centred on its axis when `along` is "y").
  function cylinder(r, h, m, along) {
    const g = new T.CylinderGeometry(r, r, h, 32);
    if (along === "y") return new T.Mesh(g, m);
    g.rotateX(Math.PI / 2);
    g.translate(0, 0, h / 2);
    return new T.Mesh(g, m);
  }
  function box(w, d, h, m, z0) {
    const g = new T.BoxGeometry(w, d, h);
    g.translate(0, 0, (z0 || 0) + h / 2);
    return new T.Mesh(g, m);
  }
  // A joint axis: a coloured cylinder along the axis the joint turns about.
  function axisMark(r, len, color, along) {
    return cylinder(r, len, mat(color), along);
  }

  // The chain: waist (about z) -> shoulder, elbow, wrist pitch (about y,
  // positive tips the arm towards +x) -> flange (roll about z) -> TCP.
  let arm = null;
  function buildArm(robot) {
    const L = robot.links;
    const root = new T.Group();
    root.add(cylinder(90, 30, GREY));
    const waist = new T.Group();
    root.add(waist);
    waist.add(cylinder(55, L.l1 - 40, ORANGE, null));
    waist.children[0].position.z = 30;
    const waistAxis = axisMark(6, L.l1 + 60, 0x2050c0);
    waistAxis.position.z = -10;
    waist.add(waistAxis);
    const shoulder = new T.Group();
    shoulder.position.z = L.l1;
    waist.add(shoulder);
    shoulder.add(axisMark(40, 150, 0x2050c0, "y"));
    shoulder.add(box(56, 70, L.l2, ORANGE));
    const elbow = new T.Group();
    elbow.position.z = L.l2;
    shoulder.add(elbow);
    elbow.add(axisMark(32, 120, 0x2050c0, "y"));
    elbow.add(box(44, 56, L.l3, ORANGE));
    const wrist = new T.Group();
    wrist.position.z = L.l3;
    elbow.add(wrist);
    wrist.add(axisMark(24, 90, 0x2050c0, "y"));
    wrist.add(box(36, 44, L.l4, LIGHT));
    const flange = new T.Group();
    flange.position.z = L.l4;
    wrist.add(flange);
    flange.add(cylinder(30, 8, GREY));
    // The hand: a palm across the flange's y axis and two jaws that open
    // along it, reaching to the TCP of the standard tool.
    const gmax = robot.gripper[1];
    flange.add(box(30, gmax + 40, 26, GREY, 8));
    const reach = Math.max(L.tool - 34, 20);
    const jaws = [-1, 1].map((s) => {
      const j = box(22, 8, reach, LIGHT, 34);
      j.userData.side = s;
      flange.add(j);
      return j;
    });
    const tcp = new T.Group();
    tcp.position.z = L.tool;
    flange.add(tcp);
    const tcpMark = new T.Mesh(new T.SphereGeometry(6, 16, 12), mat(0x202020));
    tcp.add(tcpMark);
    world.add(root);
    return { root, waist, shoulder, elbow, wrist, flange, jaws, tcp };
  }

  const D = Math.PI / 180;
  function setPose(q, grip, toolOffset) {
    arm.waist.rotation.z = q[0] * D;
    arm.shoulder.rotation.y = q[1] * D;
    arm.elbow.rotation.y = q[2] * D;
    arm.wrist.rotation.y = q[3] * D;
    arm.flange.rotation.z = q[4] * D;
    for (const j of arm.jaws) j.position.y = j.userData.side * (grip / 2 + 4);
    if (toolOffset) arm.tcp.position.copy(toolOffset);
    arm.root.updateMatrixWorld(true);
  }

  // The TCP relative to the flange for row i: from the recorded TCP, so a
  // SetTool tool is drawn where adair put it (cached per row).
  const toolCache = [];
  function toolOffset(i) {
    if (toolCache[i]) return toolCache[i];
    const r = rows[i];
    setPose(r.slice(1, 6), r[9], null);
    const v = arm.flange.worldToLocal(new T.Vector3(r[6], r[7], r[8]));
    toolCache[i] = v;
    return v;
  }

  // ---------------------------------------------------------- timeline
  // The last row at or before t (rows are in time order).
  function rowAt(t) {
    let lo = 0, hi = rows.length - 1;
    if (hi < 0) return -1;
    if (t <= rows[0][0]) return 0;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (rows[mid][0] <= t) lo = mid; else hi = mid - 1;
    }
    return lo;
  }

  // Joints (deg), grip and the row whose tool holds, at time t: linear
  // between support points, as --record describes them.
  function stateAt(t) {
    const i = rowAt(t);
    if (i < 0) return null;
    const a = rows[i];
    const b = rows[i + 1];
    let f = 0;
    if (b && b[0] > a[0] && t > a[0]) f = Math.min((t - a[0]) / (b[0] - a[0]), 1);
    const lerp = (k) => (b && f > 0 ? a[k] + (b[k] - a[k]) * f : a[k]);
    const q = [1, 2, 3, 4, 5].map(lerp);
    return { i, q, grip: lerp(9) };
  }

  function poseAt(t) {
    const s = stateAt(t);
    if (!s) return null;
    setPose(s.q, s.grip, toolOffset(s.i));
    return s;
  }

  const NAMES = ["base", "shoulder", "elbow", "wrist", "flange", "tcp"];
  function points() {
    const objs = [arm.root, arm.shoulder, arm.elbow, arm.wrist, arm.flange, arm.tcp];
    return objs.map((o) => o.getWorldPosition(new T.Vector3()));
  }

  // -------------------------------------------------------------- scene
  let trail = null, trailCap = 0;
  function trailGeometry(cap) {
    const g = new T.BufferGeometry();
    g.setAttribute("position", new T.BufferAttribute(new Float32Array(cap * 3), 3));
    return g;
  }
  function buildTrail() {
    trailCap = Math.max(1024, rows.length * 2);
    trail = new T.Line(trailGeometry(trailCap), new T.LineBasicMaterial({ color: 0x1a66cc }));
    trail.frustumCulled = false;
    world.add(trail);
    fillTrail(0);
  }
  function fillTrail(from) {
    if (rows.length > trailCap) {
      trailCap = rows.length * 2;
      trail.geometry.dispose();
      trail.geometry = trailGeometry(trailCap);
      from = 0;
    }
    const p = trail.geometry.attributes.position;
    for (let i = from; i < rows.length; i++) p.setXYZ(i, rows[i][6], rows[i][7], rows[i][8]);
    p.needsUpdate = true;
  }

  function label(text, color) {
    const c = document.createElement("canvas");
    c.width = 128; c.height = 48;
    const g = c.getContext("2d");
    g.font = "bold 30px sans-serif";
    g.fillStyle = color || "#222";
    g.textAlign = "center";
    g.textBaseline = "middle";
    g.fillText(text, 64, 24);
    const s = new T.Sprite(new T.SpriteMaterial({ map: new T.CanvasTexture(c), depthTest: false }));
    s.scale.set(120, 45, 1);
    return s;
  }

  let pathGroup = null;
  function buildPaths(paths) {
    if (pathGroup) world.remove(pathGroup);
    pathGroup = new T.Group();
    const dot = new T.SphereGeometry(7, 12, 8);
    const m = mat(0x8a2be2);
    paths.forEach((p, k) => {
      const f = p.frame;
      const at = new T.Vector3(f[0][3], f[1][3], f[2][3]);
      const s = new T.Mesh(dot, m);
      s.position.copy(at);
      pathGroup.add(s);
      if (k < 300) {
        const l = label(p.path + "." + p.pos, "#5a1a9a");
        l.position.set(at.x, at.y, at.z + 22);
        pathGroup.add(l);
      }
    });
    world.add(pathGroup);
  }

  // The device file gives a belt's end, not its direction: it is drawn
  // passing the robot, square to the line from the base to its end (so it
  // never runs through the arm). The beam of a light barrier crosses its
  // belt's end; objects are boxes of their width, placed at each time by
  // the device moments (adair's device moments, see objectAt).
  const belts = {}, beams = {}, objs = {}, objOrder = [], devLines = [];
  function buildDevices(dev) {
    if (!dev) return;
    for (const b of dev.belts) {
      const end = new T.Vector3(b.end[0], b.end[1], b.end[2]);
      const radial = new T.Vector3(end.x, end.y, 0);
      if (radial.length() < 1e-6) radial.set(1, 0, 0);
      radial.normalize();
      // dir points from the end back to the start.
      const dir = new T.Vector3(-radial.y, radial.x, 0);
      const len = b.length;
      const g = new T.BoxGeometry(len, 90, 12);
      const mesh = new T.Mesh(g, mat(0x333333));
      const mid = end.clone().addScaledVector(dir, len / 2);
      mesh.position.set(mid.x, mid.y, end.z - 26);
      mesh.rotation.z = Math.atan2(dir.y, dir.x);
      world.add(mesh);
      const tag = label(b.name, "#333");
      tag.position.set(mid.x, mid.y, end.z + 30);
      world.add(tag);
      belts[b.name] = { end, dir, len };
    }
    for (const l of dev.barriers) {
      const b = belts[l.on];
      if (!b) continue;
      const across = new T.Vector3(-b.dir.y, b.dir.x, 0).multiplyScalar(70);
      const a = b.end.clone().add(across), c = b.end.clone().sub(across);
      const g = new T.BufferGeometry().setFromPoints([a, c]);
      const line = new T.Line(g, new T.LineBasicMaterial({ color: BEAM_CLEAR }));
      world.add(line);
      beams[l.name] = { line, changes: [] };
    }
    for (const m of dev.events || []) addMoment(m);
  }
  const BEAM_CLEAR = 0xf0a0a0, BEAM_BROKEN = 0xff0000;

  // One device moment: the objects whose course changed (a new object, a
  // belt started or stopped, an arrival, a pick, a put-down), the beams
  // that changed, and what happened (the --trace texts).
  function addMoment(m) {
    for (const o of m.objects || []) {
      let ob = objs[o.name];
      if (!ob) {
        const mesh = new T.Mesh(new T.BoxGeometry(o.width, o.width, o.width), mat(0xc8a060));
        mesh.visible = false;
        world.add(mesh);
        ob = objs[o.name] = { mesh, courses: [] };
        objOrder.push(o.name);
      }
      ob.courses.push({ t: m.t, c: o });
    }
    for (const b of m.beams || []) if (beams[b.name]) beams[b.name].changes.push({ t: m.t, broken: b.broken });
    if (m.what && m.what.length) devLines.push({ t: m.t, text: m.what.join("; ") });
  }

  // The last entry of a time-ordered list at or before t (-1: none).
  function lastAt(list, t) {
    let lo = 0, hi = list.length - 1, found = -1;
    while (lo <= hi) {
      const mid = (lo + hi) >> 1;
      if (list[mid].t <= t + 1e-9) { found = mid; lo = mid + 1; } else hi = mid - 1;
    }
    return found;
  }

  // A point `position` mm from a belt's start (its end is at `len`).
  function beltPoint(b, position) {
    return b.end.clone().addScaledVector(b.dir, b.len - position);
  }

  // Where object `name` is at time t (world mm), or null before it is
  // there: on a belt, `min(position + speed * dt, stop)` from its last
  // course (as adair's device world moves it); held, at the TCP at t
  // (`tcp` when given, else the arm's at t); put down, where it lies.
  function objectAt(name, at, tcp) {
    const ob = objs[name];
    if (!ob) return null;
    const k = lastAt(ob.courses, at);
    if (k < 0) return null;
    const { t: t0, c } = ob.courses[k];
    if (c.at) return new T.Vector3(c.at[0], c.at[1], c.at[2]);
    if (c.held) {
      if (tcp) return tcp.clone();
      const s = poseAt(at);
      const p = s ? arm.tcp.getWorldPosition(new T.Vector3()) : null;
      poseAt(t);
      return p;
    }
    const b = belts[c.belt];
    if (!b) return null;
    const p = Math.max(Math.min(c.position + c.speed * Math.max(at - t0, 0), c.stop), c.position);
    return beltPoint(b, p);
  }

  // Objects and beams as they are at the time shown; the latest device
  // happening in the readout.
  function showDevices(tcp) {
    for (const name of objOrder) {
      const ob = objs[name];
      const p = objectAt(name, t, tcp);
      ob.mesh.visible = !!p;
      if (p) ob.mesh.position.copy(p);
    }
    for (const b of Object.values(beams)) {
      const k = lastAt(b.changes, t);
      b.line.material.color.setHex(k >= 0 && b.changes[k].broken ? BEAM_BROKEN : BEAM_CLEAR);
    }
    const k = lastAt(devLines, t);
    $("devices").textContent = k >= 0 ? "devices t = " + fmt(devLines[k].t, 3) + " s: " + devLines[k].text : "";
  }

  // The refused goal of a run that ended in an exception: a red frame.
  let ghost = null;
  function buildGhost(rowsOfFrame) {
    ghost = new T.Group();
    const r = rowsOfFrame;
    const o = new T.Vector3(r[0][3], r[1][3], r[2][3]);
    const m = new T.MeshBasicMaterial({ color: 0xff0000, transparent: true, opacity: 0.45 });
    const s = new T.Mesh(new T.SphereGeometry(18, 20, 14), m);
    s.position.copy(o);
    ghost.add(s);
    const lens = [90, 90, 140];
    for (let k = 0; k < 3; k++) {
      const d = new T.Vector3(r[0][k], r[1][k], r[2][k]).normalize().multiplyScalar(lens[k]);
      const g = new T.BufferGeometry().setFromPoints([o, o.clone().add(d)]);
      ghost.add(new T.Line(g, new T.LineBasicMaterial({ color: [0xff0000, 0xff6060, 0xaa0000][k] })));
    }
    // A dashed red line from where the TCP stopped to the refused goal.
    const last = rows.length ? rows[rows.length - 1] : null;
    if (last) {
      const g = new T.BufferGeometry().setFromPoints([new T.Vector3(last[6], last[7], last[8]), o]);
      const l = new T.Line(g, new T.LineDashedMaterial({ color: 0xff0000, dashSize: 20, gapSize: 12 }));
      l.computeLineDistances();
      ghost.add(l);
    }
    ghost.visible = false;
    world.add(ghost);
  }

  // ------------------------------------------------------------- camera
  const orbit = { target: new T.Vector3(0, 0, 400), r: 2600, az: -0.9, el: 0.45 };
  function placeCamera() {
    const { target: c, r, az, el } = orbit;
    camera.position.set(c.x + r * Math.cos(el) * Math.cos(az), c.y + r * Math.cos(el) * Math.sin(az), c.z + r * Math.sin(el));
    camera.lookAt(c);
  }
  const VIEWS = {
    front: [0, 0], side: [-Math.PI / 2, 0], top: [-Math.PI / 2, Math.PI / 2 - 1e-4], iso: [-Math.PI / 4, 0.6155],
  };
  function setView(name) {
    const v = VIEWS[name];
    if (!v) return;
    [orbit.az, orbit.el] = v;
    placeCamera();
    draw();
  }
  let drag = null;
  renderer.domElement.addEventListener("pointerdown", (e) => {
    drag = { x: e.clientX, y: e.clientY, pan: e.button !== 0 || e.shiftKey };
    renderer.domElement.setPointerCapture(e.pointerId);
  });
  renderer.domElement.addEventListener("pointermove", (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX; drag.y = e.clientY;
    if (drag.pan) {
      const k = orbit.r * 0.0012;
      const right = new T.Vector3().setFromMatrixColumn(camera.matrixWorld, 0);
      const up = new T.Vector3().setFromMatrixColumn(camera.matrixWorld, 1);
      orbit.target.addScaledVector(right, -dx * k).addScaledVector(up, dy * k);
    } else {
      orbit.az -= dx * 0.006;
      orbit.el = Math.max(-1.55, Math.min(1.5707, orbit.el + dy * 0.006));
    }
    placeCamera();
    draw();
  });
  renderer.domElement.addEventListener("pointerup", () => { drag = null; });
  renderer.domElement.addEventListener("contextmenu", (e) => e.preventDefault());
  renderer.domElement.addEventListener("wheel", (e) => {
    e.preventDefault();
    orbit.r = Math.max(200, Math.min(20000, orbit.r * Math.exp(e.deltaY * 0.001)));
    placeCamera();
    draw();
  }, { passive: false });

  // `#size=WxH` draws at that size whatever the window (reproducible
  // screenshots: tests and docs/images).
  const fixed = (new URLSearchParams(location.hash.slice(1)).get("size") || "").split("x").map(Number);
  function resize() {
    let w = host.clientWidth || window.innerWidth, h = host.clientHeight || window.innerHeight;
    if (fixed.length === 2 && fixed[0] > 0 && fixed[1] > 0) [w, h] = fixed;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    draw();
  }
  window.addEventListener("resize", resize);

  // ----------------------------------------------------------- controls
  let t = 0, playing = false, speed = 1, follow = live, lastFrame = null;
  const slider = $("slider");
  function duration() {
    const last = rows.length ? rows[rows.length - 1][0] : 0;
    const end = scene && scene.end ? scene.end.t : 0;
    return Math.max(last, end || 0);
  }
  const fmt = (x, n) => (Math.abs(x) < 0.5 * Math.pow(10, -n) ? 0 : x).toFixed(n);
  function show() {
    if (!arm) return;
    const s = poseAt(t);
    const total = duration();
    $("time").textContent = "t = " + fmt(t, 3) + " s / " + fmt(total, 3) + " s";
    if (s) {
      const p = arm.tcp.getWorldPosition(new T.Vector3());
      $("joints").textContent = s.q.map((x, k) => "J" + (k + 1) + " " + fmt(x, 2) + "°").join("  ");
      $("tcp").textContent = "TCP " + [p.x, p.y, p.z].map((x) => fmt(x, 1)).join(", ") + " mm   grip " + fmt(s.grip, 1) + " mm";
      trail.geometry.setDrawRange(0, s.i + 1);
      showDevices(p);
    } else {
      $("joints").textContent = "no motion yet";
      showDevices(null);
    }
    if (!slider.matches(":active")) slider.value = total > 0 ? Math.round((t / total) * 1000) : 0;
    const ended = scene && scene.end && scene.end.exception != null && t >= scene.end.t - 1e-9;
    $("message").textContent = ended ? "t = " + fmt(scene.end.t, 3) + " s: " + scene.end.exception : "";
    $("message").style.display = ended ? "block" : "none";
    if (ghost) ghost.visible = ended;
    draw();
  }
  function draw() {
    renderer.render(world, camera);
  }
  function tick(now) {
    if (playing || follow) {
      const dt = lastFrame == null ? 0 : (now - lastFrame) / 1000;
      const total = duration();
      t = Math.min(t + dt * (follow ? 1 : speed), total);
      if (playing && t >= total && !live) setPlaying(false);
      show();
    }
    lastFrame = now;
    requestAnimationFrame(tick);
  }
  function setPlaying(on) {
    playing = on;
    if (on && t >= duration() - 1e-9 && !live) t = 0;
    $("play").textContent = on ? "Pause" : "Play";
  }
  $("play").addEventListener("click", () => { follow = false; setPlaying(!playing); });
  slider.addEventListener("input", () => {
    follow = false;
    t = (slider.value / 1000) * duration();
    show();
  });
  $("speed").addEventListener("change", () => { speed = Number($("speed").value); });
  for (const name of Object.keys(VIEWS)) $("v-" + name).addEventListener("click", () => setView(name));
  if (live) {
    $("follow").style.display = "inline";
    $("follow").addEventListener("click", () => { follow = true; setPlaying(false); });
  }

  // -------------------------------------------------------------- start
  function start(sc) {
    scene = sc;
    $("title").textContent = (sc.title ? sc.title + " on the " : "") + sc.robot.name;
    arm = buildArm(sc.robot);
    buildTrail();
    buildPaths(sc.paths || []);
    buildDevices(sc.devices);
    if (sc.end && sc.end.goal) buildGhost(sc.end.goal);
    const L = sc.robot.links;
    orbit.target.set(0, 0, (L.l1 + L.l2) * 0.6);
    orbit.r = 2.3 * (L.l1 + L.l2 + L.l3 + L.l4 + L.tool);
    const h = new URLSearchParams(location.hash.slice(1));
    if (h.has("view")) [orbit.az, orbit.el] = VIEWS[h.get("view")] || VIEWS.iso;
    else [orbit.az, orbit.el] = VIEWS.iso;
    if (h.has("t")) t = Math.max(0, Math.min(Number(h.get("t")) || 0, duration()));
    placeCamera();
    resize();
    show();
    probe(h);
  }

  // The read-only hook: where the page draws each joint at time t (world
  // mm), and the joints there (deg). Tests compare it with adair's own
  // forward kinematics. It leaves the pose shown as it was.
  function jointPositions(at) {
    const s = poseAt(at);
    const p = s ? points() : null;
    poseAt(t);
    if (!p) return null;
    const out = {};
    NAMES.forEach((n, k) => { out[n] = [p[k].x, p[k].y, p[k].z]; });
    return out;
  }
  // Where the joints shown now are on the screen, in CSS pixels.
  function screenPoints() {
    camera.updateMatrixWorld();
    const w = renderer.domElement.clientWidth, h = renderer.domElement.clientHeight;
    return points().map((p) => {
      const v = p.clone().project(camera);
      return [(v.x + 1) / 2 * w, (1 - v.y) / 2 * h];
    });
  }
  // Where each object is at time t (world mm; null before it is there).
  function objectPositions(at) {
    const out = {};
    for (const name of objOrder) {
      const p = objectAt(name, at, null);
      out[name] = p ? [p.x, p.y, p.z] : null;
    }
    return out;
  }
  window.adairView = Object.freeze({
    jointPositions,
    objectAt: (name, at) => { const p = objectAt(name, at, null); return p ? [p.x, p.y, p.z] : null; },
    objectPositions,
    joints: (at) => { const s = stateAt(at); return s ? s.q : null; },
    screenPoints,
    time: () => t,
    duration,
    rowCount: () => rows.length,
    eventCount: () => events,
    ended: () => !!(scene && scene.end && scene.end.done !== false),
  });

  // `#probe=t1,t2,...` (tests, from a command line): writes the hook's
  // answers into the page as JSON, in <pre id="adair-probe">. A live page
  // answers when the program has ended.
  function probe(h) {
    if (!h.has("probe")) return;
    if (live && !(scene.end && scene.end.done)) return;
    const times = h.get("probe").split(",").filter((x) => x !== "").map(Number);
    const pre = document.createElement("pre");
    pre.id = "adair-probe";
    pre.textContent = JSON.stringify({
      rows: rows.length,
      events,
      times: times.map((x) => ({ t: x, joints: stateAt(x) && stateAt(x).q, points: jointPositions(x), objects: objectPositions(x) })),
      shown: t,
      screen: screenPoints(),
      size: [renderer.domElement.clientWidth, renderer.domElement.clientHeight],
    });
    document.body.appendChild(pre);
  }

  if (!live) {
    parseRows($("adair-record").textContent);
    start(JSON.parse($("adair-scene").textContent));
    requestAnimationFrame(tick);
    return;
  }

  // Live: the scene first, then each motion's rows when it starts. The
  // page plays them at the wall clock's pace ("follow").
  $("live").style.display = "inline";
  const src = new EventSource("events");
  src.addEventListener("scene", (e) => {
    events++;
    const sc = JSON.parse(e.data);
    if (!arm) { start(sc); return; }
    // Another robot (the REPL's `:robot`): the same cell, the new arm.
    world.remove(arm.root);
    arm = buildArm(sc.robot);
    scene.robot = sc.robot;
    $("title").textContent = (sc.title ? sc.title + " on the " : "") + sc.robot.name;
    toolCache.length = 0;
    show();
  });
  src.addEventListener("rows", (e) => {
    events++;
    const first = rows.length;
    const before = duration();
    parseRows(e.data);
    fillTrail(first);
    // A motion that starts after what was shown: play it from its start.
    if (follow && rows.length > first && rows[first][0] >= before - 1e-9) t = Math.max(t, rows[first][0]);
    show();
  });
  src.addEventListener("cut", (e) => {
    events++;
    const r = e.data.split(",").map(Number);
    while (rows.length && rows[rows.length - 1][0] >= r[0]) rows.pop();
    rows.push(r);
    toolCache.length = Math.min(toolCache.length, rows.length - 1);
    fillTrail(0);
    show();
  });
  // How the program (or a REPL entry) ended: its time, exception and
  // refused goal, the path positions; `done` when the program has ended.
  src.addEventListener("state", (e) => {
    events++;
    const st = JSON.parse(e.data);
    scene.end = st;
    buildPaths(st.paths || []);
    if (ghost) { world.remove(ghost); ghost = null; }
    if (st.goal) buildGhost(st.goal);
    $("live").textContent = st.done ? "ended" : "live";
    show();
    if (st.done) probe(new URLSearchParams(location.hash.slice(1)));
  });
  // A device moment, in order with the motions.
  src.addEventListener("devices", (e) => {
    events++;
    addMoment(JSON.parse(e.data));
    show();
  });
  src.onerror = () => { $("live").textContent = "disconnected"; };
  requestAnimationFrame(tick);
})();
