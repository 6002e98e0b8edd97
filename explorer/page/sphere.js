// sphere.js — the sphere view: the projection (and its inverse for a click), the curve with its
// nodes and cusps (the markers as X.marks says: draw/mark_density.hpp's rule, with its note when
// they are hidden), the train at the animated carrier angle (pitch circles, pitch cones, the
// tracer), and the view's input (drag to turn, wheel to zoom about the pointer). The cones are
// off by default on a dense curve (X.marks.dense: the rule hides its markers); the cones box
// still turns them on.
// drawPathSphere draws any closed path of unit vectors on a sphere of its own canvas and view (the
// clinostat panel's gravity path), with the same projection and front/back strokes.
'use strict';
{
  const X = window.Explorer;
  const { $ } = X;
  const view = X.view;

  // [x, y, front] of the unit vector p on `canvas` (the sphere view's by default) seen as `v` says
  // ({spin, tilt, zoom, panX, panY}; the sphere view's by default).
  function project(p, canvas = $('sphere'), v = view) {
    const cs = Math.cos(v.spin), ss = Math.sin(v.spin), ct = Math.cos(v.tilt), st = Math.sin(v.tilt);
    const x1 = cs * p[0] - ss * p[1], y1 = ss * p[0] + cs * p[1], z1 = p[2];
    const y2 = ct * y1 - st * z1, z2 = st * y1 + ct * z1; // tilt about the screen's x axis
    const radius = 0.46 * canvas.width * v.zoom;
    return [canvas.width / 2 + v.panX + radius * x1, canvas.height / 2 + v.panY - radius * z2, y2 < 0];
  }

  // The point of the front half of the sphere under a pointer event (project() inverted), or null
  // off the sphere.
  function unproject(canvas, ev) {
    const rect = canvas.getBoundingClientRect();
    const radius = 0.46 * canvas.width * view.zoom;
    const x1 = ((ev.clientX - rect.left) * canvas.width / rect.width - canvas.width / 2 - view.panX) / radius;
    const z2 = -((ev.clientY - rect.top) * canvas.height / rect.height - canvas.height / 2 - view.panY) / radius;
    if (x1 * x1 + z2 * z2 >= 1) return null;
    const y2 = -Math.sqrt(1 - x1 * x1 - z2 * z2);  // the front half (project(): y2 < 0)
    const cs = Math.cos(view.spin), ss = Math.sin(view.spin), ct = Math.cos(view.tilt), st = Math.sin(view.tilt);
    const y1 = ct * y2 + st * z2, z1 = -st * y2 + ct * z2;
    return [cs * x1 + ss * y1, -ss * x1 + cs * y1, z1];
  }

  // The polyline of `count` points (x0 y0 z0 x1 ...) as runs on the front (solid) and the back
  // (faint); `at` projects a point (project() of the sphere view by default).
  function strokeRuns(ctx, points, count, frontStyle, backStyle, closed, at = project) {
    for (const front of [false, true]) {
      ctx.beginPath();
      let open = false;
      for (let k = 0; k <= count - (closed ? 0 : 1); ++k) {
        const i = k % count;
        const s = at([points[3 * i], points[3 * i + 1], points[3 * i + 2]]);
        if (s[2] === front) {
          if (open) ctx.lineTo(s[0], s[1]); else ctx.moveTo(s[0], s[1]);
          open = true;
        } else {
          open = false;
        }
      }
      ctx.strokeStyle = front ? frontStyle : backStyle;
      ctx.lineWidth = front ? 1.4 : 1;
      ctx.stroke();
    }
  }

  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const normalize = (a) => { const l = Math.hypot(a[0], a[1], a[2]); return [a[0] / l, a[1] / l, a[2] / l]; };

  function circlePoints(axis, radius) {
    const w = axis;
    const u = Math.abs(w[2]) < 0.9 ? normalize(cross(w, [0, 0, 1])) : normalize(cross(w, [1, 0, 0]));
    const v = cross(w, u);
    const pts = new Float64Array(3 * 180);
    for (let k = 0; k < 180; ++k) {
      const phi = 2 * Math.PI * k / 180;
      for (let d = 0; d < 3; ++d)
        pts[3 * k + d] = Math.cos(radius) * w[d] + Math.sin(radius) * (Math.cos(phi) * u[d] + Math.sin(phi) * v[d]);
    }
    return pts;
  }

  // The sphere's disc on a cleared canvas.
  function drawDisc(ctx, canvas, v) {
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    const centre = project([0, 0, 0], canvas, v);
    ctx.beginPath();
    ctx.arc(centre[0], centre[1], 0.46 * canvas.width * v.zoom, 0, 2 * Math.PI);
    ctx.fillStyle = '#f4f6fa';
    ctx.fill();
    ctx.strokeStyle = '#9aa4b2';
    ctx.lineWidth = 1;
    ctx.stroke();
  }

  function drawSphere() {
    const canvas = $('sphere');
    const ctx = canvas.getContext('2d');
    drawDisc(ctx, canvas, view);
    if (!X.result || !X.curve) return;
    const pts = X.curve.points, count = pts.length / 3;
    strokeRuns(ctx, pts, count, '#1c2733', 'rgba(28,39,51,0.18)', true);
    drawTrain(ctx);
    if (X.marks.draw) drawMarks(ctx);  // over the cones: whatever the carrier angle, they stay seen
    X.drawPath(ctx);
  }

  // The node points (discs) and the cusps (triangles), faint on the back half.
  function drawMarks(ctx) {
    const np = X.result.nodePositions;
    for (let i = 0; i < np.length / 3; ++i) {
      const s = project([np[3 * i], np[3 * i + 1], np[3 * i + 2]]);
      ctx.beginPath();
      ctx.arc(s[0], s[1], 3.2, 0, 2 * Math.PI);
      ctx.fillStyle = s[2] ? '#d62828' : 'rgba(214,40,40,0.3)';
      ctx.fill();
    }
    const cp = X.result.cuspPositions;
    for (let i = 0; i < cp.length / 3; ++i) {
      const s = project([cp[3 * i], cp[3 * i + 1], cp[3 * i + 2]]);
      ctx.beginPath();
      ctx.moveTo(s[0], s[1] - 5); ctx.lineTo(s[0] - 4.5, s[1] + 3.5); ctx.lineTo(s[0] + 4.5, s[1] + 3.5); ctx.closePath();
      ctx.fillStyle = s[2] ? '#f77f00' : 'rgba(247,127,0,0.35)';
      ctx.fill();
    }
  }

  // The train at carrier angle theta: the sun's pitch circle (angle a_s about Z), the planet's
  // (angle a_p about its axis Rz(theta) Rx(a2) Z), touching where the cones roll, and the tracer.
  function drawTrain(ctx) {
    const r = X.result, curve = X.curve, theta = view.theta % r.period;
    const ap = r.planetCone, as = r.a2 - ap;
    const axis = [Math.sin(r.a2) * Math.sin(theta), -Math.sin(r.a2) * Math.cos(theta), Math.cos(r.a2)];
    const sunDrawn = as > 1e-9 && as < Math.PI - 1e-9;
    if ($('cones').checked) {
      if (sunDrawn) drawCone(ctx, [0, 0, 1], as, '29,111,216');
      drawCone(ctx, axis, ap, '42,157,75');
    }
    if (sunDrawn) strokeRuns(ctx, circlePoints([0, 0, 1], as), 180, '#1d6fd8', 'rgba(29,111,216,0.25)', true);
    strokeRuns(ctx, circlePoints(axis, ap), 180, '#2a9d4b', 'rgba(42,157,75,0.25)', true);
    const count = curve.points.length / 3;
    const i = Math.round(theta / r.period * count) % count;
    const tip = project([curve.points[3 * i], curve.points[3 * i + 1], curve.points[3 * i + 2]]);
    const hub = project(axis);
    ctx.beginPath();
    ctx.moveTo(hub[0], hub[1]);
    ctx.lineTo(tip[0], tip[1]);
    ctx.strokeStyle = '#2a9d4b';
    ctx.stroke();
    ctx.beginPath();
    ctx.arc(tip[0], tip[1], 4.5, 0, 2 * Math.PI);
    ctx.fillStyle = '#7b2cbf';
    ctx.fill();
  }

  // A pitch cone: apex at the centre, half-angle `angle` about `axis`, its base the pitch circle on
  // the sphere: a light surface and a generator every 30 degrees (front solid, back faint), light
  // enough that the curve reads through them.
  function drawCone(ctx, axis, angle, rgb) {
    const pts = circlePoints(axis, angle), count = pts.length / 3;
    const apex = project([0, 0, 0]);
    const at = (k) => project([pts[3 * k], pts[3 * k + 1], pts[3 * k + 2]]);
    ctx.beginPath();
    for (let k = 0; k < count; ++k) {
      const a = at(k), b = at((k + 1) % count);
      ctx.moveTo(apex[0], apex[1]); ctx.lineTo(a[0], a[1]); ctx.lineTo(b[0], b[1]); ctx.closePath();
    }
    ctx.fillStyle = 'rgba(' + rgb + ',0.04)';
    ctx.fill('nonzero');
    for (let k = 0; k < count; k += count / 12) {
      const a = at(k);
      ctx.beginPath();
      ctx.moveTo(apex[0], apex[1]);
      ctx.lineTo(a[0], a[1]);
      ctx.strokeStyle = 'rgba(' + rgb + ',' + (a[2] ? 0.25 : 0.08) + ')';  // project(): [2] is true in front
      ctx.lineWidth = 0.8;
      ctx.stroke();
    }
  }

  // The markers' note (empty when every marker is drawn), and the cones' default: off on a dense
  // curve, on otherwise, set when the current state's density differs from the last state's (a
  // user's choice holds while it does not).
  let lastDense = null;
  function followDensity() {
    const note = X.byTestId('marks-note');
    note.textContent = X.marks ? X.marks.note : '';
    if (!X.marks || X.marks.dense === lastDense) return;
    lastDense = X.marks.dense;
    $('cones').checked = !lastDense;
  }

  // Turns the view to look from the unit vector d (towards the viewer): project() puts d at the
  // centre, on the front half, with +Z pointing up the screen (spin about Z brings d into the
  // screen's depth-height plane on the viewer's side, tilt about the screen's x axis raises it to
  // face the viewer).
  function lookFrom(d) {
    const h = Math.hypot(d[0], d[1]);
    view.spin = h > 1e-9 ? Math.atan2(-d[0], -d[1]) : 0;
    view.tilt = Math.atan2(d[2], h);
  }

  function setupSphereInput() {
    const canvas = $('sphere');
    let drag = null;
    canvas.addEventListener('pointerdown', (ev) => { drag = { x: ev.clientX, y: ev.clientY }; canvas.setPointerCapture(ev.pointerId); });
    canvas.addEventListener('pointermove', (ev) => {
      if (!drag) return;
      view.turnedByHand = true;
      view.spin += (ev.clientX - drag.x) * 0.01 / Math.sqrt(view.zoom);
      view.tilt += (ev.clientY - drag.y) * 0.01 / Math.sqrt(view.zoom);
      drag = { x: ev.clientX, y: ev.clientY };
      drawSphere();
    });
    canvas.addEventListener('pointerup', () => { drag = null; });
    $('cones').addEventListener('change', drawSphere);
    canvas.addEventListener('wheel', (ev) => {
      ev.preventDefault();
      const rect = canvas.getBoundingClientRect();
      const cx = (ev.clientX - rect.left) * canvas.width / rect.width - canvas.width / 2;
      const cy = (ev.clientY - rect.top) * canvas.height / rect.height - canvas.height / 2;
      const factor = Math.exp(-ev.deltaY * 0.0015);
      const zoom = Math.min(1e5, Math.max(1, view.zoom * factor));
      const f = zoom / view.zoom;
      view.panX = zoom === 1 ? 0 : cx - (cx - view.panX) * f;
      view.panY = zoom === 1 ? 0 : cy - (cy - view.panY) * f;
      view.zoom = zoom;
      drawSphere();
    }, { passive: false });
  }

  // A closed path of unit vectors (x0 y0 z0 x1 ..., or null: the disc alone) on `canvas` seen as
  // `v`, its first point marked (violet) and the coordinate axes' ends labelled on the front.
  function drawPathSphere(canvas, v, points) {
    const ctx = canvas.getContext('2d');
    const at = (p) => project(p, canvas, v);
    drawDisc(ctx, canvas, v);
    ctx.font = '11px sans-serif';
    for (const [label, p] of [['+X', [1, 0, 0]], ['+Y', [0, 1, 0]], ['+Z', [0, 0, 1]]]) {
      const s = at(p);
      ctx.fillStyle = s[2] ? '#556' : 'rgba(85,85,102,0.35)';
      ctx.fillText(label, s[0] + 3, s[1] - 3);
    }
    if (!points || points.length < 3) return;
    const count = points.length / 3;
    if (count > 1) strokeRuns(ctx, points, count, '#1c2733', 'rgba(28,39,51,0.18)', true, at);
    const s = at([points[0], points[1], points[2]]);
    ctx.beginPath();
    ctx.arc(s[0], s[1], 4.5, 0, 2 * Math.PI);
    ctx.fillStyle = '#7b2cbf';
    ctx.fill();
  }

  // Drag on `canvas` turns `v` and calls redraw().
  function turnOnDrag(canvas, v, redraw) {
    let drag = null;
    canvas.addEventListener('pointerdown', (ev) => { drag = { x: ev.clientX, y: ev.clientY }; canvas.setPointerCapture(ev.pointerId); });
    canvas.addEventListener('pointermove', (ev) => {
      if (!drag) return;
      v.spin += (ev.clientX - drag.x) * 0.01;
      v.tilt += (ev.clientY - drag.y) * 0.01;
      drag = { x: ev.clientX, y: ev.clientY };
      redraw();
    });
    canvas.addEventListener('pointerup', () => { drag = null; });
  }

  function animate(time) {
    if ($('animate').checked && X.result) {
      view.theta = (time / 1000) * 0.6 * Math.max(1, X.result.q / 2);
      drawSphere();
    }
    window.requestAnimationFrame(animate);
  }

  Object.assign(X, { project, unproject, lookFrom, drawSphere, followDensity, setupSphereInput, animate, drawPathSphere,
    turnOnDrag });
}
