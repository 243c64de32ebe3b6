'use strict';
// The little vector and quaternion algebra the adapters need. Quaternions
// here are [w, x, y, z], as in the world file; each engine's own order is
// converted at its boundary.

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const norm = (a) => Math.hypot(a[0], a[1], a[2]);
const unit = (a) => scale(a, 1 / norm(a));

function qmul(a, b) {
  return [
    a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
    a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
    a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
    a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
  ];
}
const qconj = (q) => [q[0], -q[1], -q[2], -q[3]];
function qnormalize(q) {
  const n = Math.hypot(q[0], q[1], q[2], q[3]);
  return q.map((c) => c / n);
}
// v rotated by q.
function rotate(q, v) {
  const r = qmul(qmul(q, [0, v[0], v[1], v[2]]), qconj(q));
  return [r[1], r[2], r[3]];
}
// The rotation matrix of q, rows.
function matrix(q) {
  const [w, x, y, z] = q;
  return [
    [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
    [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
    [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
  ];
}
// The quaternion of a proper rotation matrix (rows).
function fromMatrix(m) {
  const t = m[0][0] + m[1][1] + m[2][2];
  let q;
  if (t > 0) {
    const s = Math.sqrt(t + 1) * 2;
    q = [s / 4, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s];
  } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
    const s = Math.sqrt(1 + m[0][0] - m[1][1] - m[2][2]) * 2;
    q = [(m[2][1] - m[1][2]) / s, s / 4, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s];
  } else if (m[1][1] > m[2][2]) {
    const s = Math.sqrt(1 + m[1][1] - m[0][0] - m[2][2]) * 2;
    q = [(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, s / 4, (m[1][2] + m[2][1]) / s];
  } else {
    const s = Math.sqrt(1 + m[2][2] - m[0][0] - m[1][1]) * 2;
    q = [(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, s / 4];
  }
  return qnormalize(q);
}
// A rotation whose x axis is `xAxis` and whose y axis is as near `hint`
// as it can be: the frame a constraint is given in.
function frameFrom(xAxis, hint) {
  const x = unit(xAxis);
  let h = hint && Math.abs(dot(unit(hint), x)) < 0.9 ? hint : Math.abs(x[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
  const z = unit(cross(x, h));
  const y = cross(z, x);
  return fromMatrix([[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]);
}
// Any unit vector perpendicular to `a`.
function perpendicular(a) {
  const u = unit(a);
  return unit(cross(u, Math.abs(u[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0]));
}

// The principal moments and axes of a symmetric inertia tensor given as
// [xx, yy, zz, xy, xz, yz] (Jacobi rotations): {moments, rotation} with
// rotation the quaternion of the principal frame in the body's frame.
function principalInertia(inertia) {
  const [xx, yy, zz, xy, xz, yz] = inertia;
  if (xy === 0 && xz === 0 && yz === 0) return { moments: [xx, yy, zz], rotation: [1, 0, 0, 0] };
  const a = [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]];
  const v = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
  for (let sweep = 0; sweep < 50; ++sweep) {
    const off = Math.abs(a[0][1]) + Math.abs(a[0][2]) + Math.abs(a[1][2]);
    if (off < 1e-15 * (Math.abs(a[0][0]) + Math.abs(a[1][1]) + Math.abs(a[2][2]))) break;
    for (const [p, q] of [[0, 1], [0, 2], [1, 2]]) {
      if (a[p][q] === 0) continue;
      const theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
      const t = Math.sign(theta || 1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
      const c = 1 / Math.sqrt(t * t + 1), s = t * c;
      for (let k = 0; k < 3; ++k) {  // a = J^T a J, v = v J
        const akp = a[k][p], akq = a[k][q];
        a[k][p] = c * akp - s * akq;
        a[k][q] = s * akp + c * akq;
      }
      for (let k = 0; k < 3; ++k) {
        const apk = a[p][k], aqk = a[q][k];
        a[p][k] = c * apk - s * aqk;
        a[q][k] = s * apk + c * aqk;
      }
      for (let k = 0; k < 3; ++k) {
        const vkp = v[k][p], vkq = v[k][q];
        v[k][p] = c * vkp - s * vkq;
        v[k][q] = s * vkp + c * vkq;
      }
    }
  }
  // Columns of v are the axes; make it a proper rotation.
  const det = v[0][0] * (v[1][1] * v[2][2] - v[1][2] * v[2][1]) - v[0][1] * (v[1][0] * v[2][2] - v[1][2] * v[2][0])
    + v[0][2] * (v[1][0] * v[2][1] - v[1][1] * v[2][0]);
  if (det < 0) for (let k = 0; k < 3; ++k) v[k][2] = -v[k][2];
  return { moments: [a[0][0], a[1][1], a[2][2]], rotation: fromMatrix(v) };
}

// Capsules and cylinders lie along local z in ODE and along local y in
// Jolt and Rapier: this turns y onto z (90 degrees about x).
const Y_TO_Z = [Math.SQRT1_2, Math.SQRT1_2, 0, 0];

module.exports = { dot, cross, scale, add, sub, norm, unit, qmul, qconj, qnormalize, rotate, matrix, fromMatrix,
  frameFrom, perpendicular, principalInertia, Y_TO_Z };
