'use strict';
// What every web peer builds the same way: the composite pendulum's mass
// properties (as peers/bullet_lab.cpp works them out), and the kinetic energy
// and tilt of a body from its velocity, spin and orientation.
const { scene, SURFACE_GRAVITY } = require('./constants');

// The rod and the bob as one body: its mass, the anchor-to-centre distance
// along +x and the principal moments about the centre (x along the rod).
function pendulumMass(bobMass) {
  const { ROD_MASS, ROD_LENGTH, ROD_THICKNESS, BOB_RADIUS, BOB_DISTANCE } = scene.test2;
  const mass = ROD_MASS + bobMass;
  const centre = (ROD_MASS * ROD_LENGTH / 2 + bobMass * BOB_DISTANCE) / mass;
  const bobOwn = 0.4 * bobMass * BOB_RADIUS * BOB_RADIUS;
  const rodAlong = (ROD_MASS * 2 * ROD_THICKNESS * ROD_THICKNESS) / 12;
  const rodAcross = (ROD_MASS * (ROD_LENGTH * ROD_LENGTH + ROD_THICKNESS * ROD_THICKNESS)) / 12 +
    ROD_MASS * (ROD_LENGTH / 2 - centre) ** 2;
  const across = rodAcross + bobOwn + bobMass * (BOB_DISTANCE - centre) ** 2;
  return { mass, centre, inertia: [rodAlong + bobOwn, across, across],
    rodOffset: ROD_LENGTH / 2 - centre, bobOffset: BOB_DISTANCE - centre };
}

// q^-1 v q for a unit quaternion [x, y, z, w]: a world vector in body axes.
function toBody(q, v) {
  const [x, y, z, w] = q;
  // v' = v + 2 r x (r x v + w' v) with r = -q.xyz, w' = w
  const rx = -x, ry = -y, rz = -z;
  const cx = ry * v[2] - rz * v[1] + w * v[0];
  const cy = rz * v[0] - rx * v[2] + w * v[1];
  const cz = rx * v[1] - ry * v[0] + w * v[2];
  return [v[0] + 2 * (ry * cz - rz * cy), v[1] + 2 * (rz * cx - rx * cz), v[2] + 2 * (rx * cy - ry * cx)];
}

// 0.5 m v^2 + 0.5 w^T I w, I the principal moments in body axes.
function kineticEnergy(mass, inertia, velocity, spin, orientation) {
  const w = toBody(orientation, spin);
  const v2 = velocity[0] ** 2 + velocity[1] ** 2 + velocity[2] ** 2;
  return 0.5 * mass * v2 + 0.5 * (inertia[0] * w[0] ** 2 + inertia[1] * w[1] ** 2 + inertia[2] * w[2] ** 2);
}

// The angle between a body's local y axis and world y, in degrees.
function tiltDegrees(q) {
  const [x, , z] = q;
  const up = 1 - 2 * (x * x + z * z);  // world y of the local y axis
  return (Math.acos(Math.max(-1, Math.min(1, up))) * 180) / Math.PI;
}

// The stack's readout, for every engine whose contacts cannot be read back
// cheaply: overlap from the centres' heights (exact while the cubes stand upright).
// `world`: {step(), position(body), transform(body) -> [position, quaternion]}.
function stackReadout(world, small, big) {
  const t = scene.test4;
  return {
    step: () => world.step(),
    bigCentre: () => world.position(big),
    bigTiltDegrees: () => tiltDegrees(world.transform(big)[1]),
    deepestPenetration: () => {
      const s = world.position(small)[1], b = world.position(big)[1];
      return Math.max(0, s + t.SMALL_SIDE / 2 - (b - t.BIG_SIDE / 2), -(s - t.SMALL_SIDE / 2));
    },
  };
}

// How far the lowest corner of a cube of side `side` is below y = 0 (0 if
// above): each local axis reaches |its world y| x half the side.
function depthBelowGround(position, q, side) {
  const [x, y, z, w] = q;
  const row = [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)];
  const reach = (side / 2) * row.reduce((sum, r) => sum + Math.abs(r), 0);
  return Math.max(0, reach - position[1]);
}

// test6's readout from any engine's positions and orientations.
// `world`: {step(), position(body), rotation(body)}.
function uprightReadout(world, small, big) {
  const t = scene.test6;
  return {
    step: () => world.step(),
    bigCentre: () => world.position(big),
    bigTiltDegrees: () => tiltDegrees(world.rotation(big)),
    smallSink: () => depthBelowGround(world.position(small), world.rotation(small), t.SMALL_SIDE),
  };
}

// test10's launch, as the measurement reads it, for an engine whose world
// wrapper has step(), position(body), velocity(body) and dispose().
function launchedCube(world, cube) {
  return {
    step: () => world.step(),
    cubeCentre: () => world.position(cube),
    cubeVelocityX: () => world.velocity(cube)[0],
    dispose: () => world.dispose(),
  };
}

// test7's throw (tests/scenes/test7's throwTestCube): from THROW_DISTANCE
// before the pivot, level with it, unturned, aimed up by a with
// sin 2a = g d / v^2 so that its arc comes back to that level at the pivot.
function throwState() {
  const t = scene.test7;
  const a = 0.5 * Math.asin((SURFACE_GRAVITY * t.THROW_DISTANCE) / t.THROW_SPEED ** 2);
  return { position: [-t.THROW_DISTANCE, t.PIVOT_CENTRE_Y, 0],
    velocity: [t.THROW_SPEED * Math.cos(a), t.THROW_SPEED * Math.sin(a), 0] };
}

// The point at height y on a body's local y axis, in world coordinates.
function pointOnY(position, q, y) {
  const [x, qy, z, w] = q;
  const column = [2 * (x * qy - w * z), 1 - 2 * (x * x + z * z), 2 * (qy * z + w * x)];
  return position.map((p, i) => p + y * column[i]);
}

// test7's readout: each ball joint's error (where the two joined bodies, or
// the fixed point, hold its anchor), the larger of the two, and the pivot's spin.
// `world`: {step(), position(body), rotation(body), spin(body)}; `throwCube()`: the engine's.
function hangingPairReadout(world, pivot, big, cube, throwCube) {
  const t = scene.test7;
  const on = (body, y) => pointOnY(world.position(body), world.rotation(body), y);
  const gap = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  return {
    step: () => world.step(),
    throwCube,
    jointError: () => Math.max(gap(on(pivot, t.PIVOT_SIDE / 2), [0, t.ANCHOR_HEIGHT, 0]),
      gap(on(pivot, -t.PIVOT_SIDE / 2), on(big, t.BIG_SIDE / 2))),
    pivotAngularSpeed: () => Math.hypot(...world.spin(pivot)),
    pivotCentre: () => world.position(pivot),
    testCubeCentre: () => world.position(cube),
  };
}

// test3's dominoes as peers/Test3Scene.h builds them (the C++ peers' copy
// of test3's placements): centre, orientation [x, y, z, w], and the first
// one's push (velocity and spin). The same-scene check holds both to test3.
function dominoStarts(count) {
  const t = scene.test3;
  const starts = [];
  const growth = t.SPIRAL_PITCH / (2 * Math.PI);
  let angle = 0;
  for (let i = 0; i < count; ++i) {
    const r = t.SPIRAL_START_RADIUS + growth * angle;
    const c = Math.cos(angle), s = Math.sin(angle);
    const dx = growth * c - r * s, dz = growth * s + r * c, length = Math.hypot(dx, dz);
    const tx = dx / length, tz = dz / length;
    angle += t.DOMINO_SPACING / length;
    const yaw = Math.atan2(-tz, tx) / 2, lean = ((i === 0 ? t.FIRST_TILT_DEGREES : 0) * Math.PI) / 360;
    const a = [Math.cos(lean), tz * Math.sin(lean), 0, -tx * Math.sin(lean)];  // w, x, y, z
    const b = [Math.cos(yaw), 0, Math.sin(yaw), 0];
    const w = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    const x = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    const y = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    const z = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
    const q = [x, y, z, w];
    const pivot = [r * c + (tx * t.DOMINO_THICKNESS) / 2, 0, r * s + (tz * t.DOMINO_THICKNESS) / 2];
    const arm = toBody([-x, -y, -z, w], [-t.DOMINO_THICKNESS / 2, t.DOMINO_HEIGHT / 2, 0]);  // q arm q^-1
    const start = { centre: [pivot[0] + arm[0], arm[1], pivot[2] + arm[2]], rotation: q, velocity: [0, 0, 0], spin: [0, 0, 0] };
    if (i === 0) {
      const o = [t.FIRST_PUSH * tz, 0, -t.FIRST_PUSH * tx];
      start.spin = o;
      start.velocity = [o[1] * arm[2] - o[2] * arm[1], o[2] * arm[0] - o[0] * arm[2], o[0] * arm[1] - o[1] * arm[0]];
    }
    starts.push(start);
  }
  return starts;
}

// How far a body's local x axis is turned about the vertical, in degrees
// (test5's twist, from an orientation [x, y, z, w]).
function yawDegrees(q) {
  const [x, y, z, w] = q;
  return (Math.atan2(-2 * (x * z - w * y), 1 - 2 * (y * y + z * z)) * 180) / Math.PI;
}

// test5's plates as the measurement reads them, for an engine that makes a
// plate with `makePlate(height)` -> body and reads it back through `world`:
// {step(), position(body), rotation(body), velocity(body)}.
function plateStack(world, makePlate) {
  const plates = [];
  return {
    step: () => world.step(),
    dropPlate: (height) => plates.push(makePlate(height)),
    count: () => plates.length,
    plateCentre: (i) => world.position(plates[i]),
    plateSpeed: (i) => Math.hypot(...world.velocity(plates[i])),
    plateYawDegrees: (i) => yawDegrees(world.rotation(plates[i])),
  };
}

module.exports = { plateStack, dominoStarts, pendulumMass, kineticEnergy, tiltDegrees, stackReadout, uprightReadout, launchedCube, throwState,
  hangingPairReadout };
