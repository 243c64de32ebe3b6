#!/usr/bin/env node
'use strict';
// The floor an engine adapter is measured against: one WebAssembly engine's
// npm build stepping a world file's world in a tight loop, with none of the
// lab's adapter code around it (no session, no protocol, no world model, no
// material planning, no contact callbacks, no step clock).
//
//   node peers/wasm/bench/bare.js ENGINE WORLD.json [--steps N] [--repeats R] [--warmup W] [--states]
//
// ENGINE: havok, jolt or rapier. It builds the world with the engine's own
// JS API, then times STEPS steps (default 2000), each one the engine's own
// step call timed alone (as the adapter's engine_wall_seconds times it),
// and after each step reads every dynamic body's position and orientation
// into one preallocated array, the cheapest per-body read each API offers
// (what an adapter has to do too). Each repeat builds the world afresh.
// W warm-up repeats (default 1) run first, untimed but for the first one:
// V8 runs a WebAssembly module's code first from its baseline compiler and
// swaps in optimised code while it runs, so a fresh process's first
// thousands of steps are slower (measured: several times slower for Rapier
// on a loaded machine), and the floor is the engine's steady state.
// It prints one JSON line: engine, world, steps, repeats, bodies,
// cold_step_seconds (the first warm-up's per step: what a fresh process
// gets, as an adapter's run does), step_seconds (median per step over the
// timed repeats, with min and max) and
// loop_seconds (the whole loop, reads and drops included, per step);
// with --states, `states`: each body's last position and orientation
// ([x, y, z, w, qx, qy, qz], null for one not yet dropped in), to hold
// the harness's world against the adapter's (odelab_engine_step).
//
// Only what the benchmarked worlds need is built (checks/bench_engine_overhead.py): spheres, boxes and a
// y-up plane; ball and hinge joints to the static world or another body;
// diagonal inertia; "drop" events (a body appears at its time). Anything
// else is refused, naming it, before an engine is loaded (status 2).
// A geom with category or collide bits 0 touches nothing and is left out;
// other collide bits are refused.
//
// Settings matched to each adapter's "default" (peers/wasm/src/engines/):
// - all: the world's step and gravity; masses and inertia as given;
//   friction mu = infinity as 1e6; each geom's friction and restitution
//   from its surface against the static geoms (else the default surface),
//   the engine's own combine rule (the adapters choose a rule per world);
//   no sleeping unless a body has auto-disable (none in these scenes);
// - rapier: its default integration parameters (4 solver iterations,
//   lengthUnit 1), a plane as a 1000 x 10 x 1000 m static cuboid (as the
//   adapter: the JS API has no half-space), joined bodies not touching;
// - havok: its default damping, speed caps and ideal step time (1/60 s),
//   a plane as a static 1000 x 10 x 1000 m box, every body always active,
//   joints as 6-DOF constraints with the held axes locked and the free ones
//   frictionless, collisions between joined bodies off;
// - jolt: its default physics settings (10 velocity, 2 position
//   iterations), damping and caps, Step(h, 1), its plane shape 2000 m
//   across, boxes with the default 0.05 m convex radius, a body's shape
//   shifted so that its origin is the world's centre of mass.
const fs = require('fs');
const path = require('path');
const { STATIC, MOVING, joltInterface } = require('../src/engines/jolt_interface');

const LARGEST_FRICTION = 1e6;
const PLANE_SIDE = 1000, PLANE_DEPTH = 10;
const ALL_BITS = 0xffffffff;

class Refused extends Error {}

function usage() {
  return 'usage: node bare.js havok|jolt|rapier WORLD.json [--steps N] [--repeats R] [--warmup W] [--states]';
}

function parseArgs(argv) {
  const positional = [];
  const options = { steps: 2000, repeats: 5, warmup: 1, states: false };
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    if (a === '--steps' || a === '--repeats' || a === '--warmup') {
      const v = Number(argv[++i]);
      const least = a === '--warmup' ? 0 : 1;
      if (!Number.isInteger(v) || v < least) throw new Refused(`${a}: a whole number >= ${least}, got ${JSON.stringify(argv[i])}`);
      options[a.slice(2)] = v;
    } else if (a === '--states') {
      options.states = true;
    } else if (a.startsWith('--')) {
      throw new Refused(`unknown option ${a}`);
    } else {
      positional.push(a);
    }
  }
  if (positional.length !== 2) throw new Refused(usage());
  [options.engine, options.world] = positional;
  if (!['havok', 'jolt', 'rapier'].includes(options.engine))
    throw new Refused(`engine '${options.engine}': this harness steps havok, jolt or rapier`);
  return options;
}

const number = (x) => (x === 'infinity' ? Infinity : x);

// The world file reduced to what the harness builds, or refused naming what it lacks.
function readWorld(file) {
  let w;
  try {
    w = JSON.parse(fs.readFileSync(file, 'utf8'));
  } catch (error) {
    throw new Refused(`${file}: ${error.message}`);
  }
  if (w.format !== 'odelab-world') throw new Refused(`${file}: not an odelab-world file`);
  const s = w.settings;
  const bodies = (w.bodies || []).map((b, i) => {
    const inertia = b.inertia;
    if (inertia[3] || inertia[4] || inertia[5]) throw new Refused(`bodies[${i}]: inertia with products (not diagonal): not built here`);
    if (b.kinematic) throw new Refused(`bodies[${i}]: kinematic: not built here`);
    if (b.auto_disable && b.auto_disable.on) throw new Refused(`bodies[${i}]: auto_disable: not built here`);
    return {
      mass: b.mass, inertia: inertia.slice(0, 3), position: b.position, orientation: b.orientation || [1, 0, 0, 0],
      linearVelocity: b.linear_velocity || [0, 0, 0], angularVelocity: b.angular_velocity || [0, 0, 0],
      gravity: b.gravity !== false, geoms: [], dropStep: 0,
    };
  });
  const surfaces = w.surfaces.map((sf) => ({
    mu: Math.min(number(sf.mu), LARGEST_FRICTION),
    restitution: sf.restitution !== undefined && sf.bounce_velocity !== undefined ? sf.restitution : (sf.restitution || 0),
  }));
  const pairSurface = new Map();
  for (const p of w.pair_surfaces || []) pairSurface.set(`${Math.min(...p.geoms)},${Math.max(...p.geoms)}`, p.surface);
  const defaultSurface = w.default_surface || 0;
  const statics = [];
  const geoms = [];
  w.geoms.forEach((g, i) => {
    if (!['sphere', 'box', 'plane'].includes(g.shape)) throw new Refused(`geoms[${i}]: shape '${g.shape}': not built here (sphere, box, plane)`);
    const category = g.category === undefined ? ALL_BITS : g.category, collide = g.collide === undefined ? ALL_BITS : g.collide;
    if (category === 0 || collide === 0) return;  // touches nothing
    if (category !== ALL_BITS || collide !== ALL_BITS) throw new Refused(`geoms[${i}]: collide bits other than all or none: not built here`);
    if (g.shape === 'plane') {
      const [a, b, c] = g.plane;
      if (a !== 0 || b !== 1 || c !== 0) throw new Refused(`geoms[${i}]: a plane whose normal is not +y: not built here`);
    }
    const orientation = g.orientation || [1, 0, 0, 0];
    if (g.shape !== 'plane' && (orientation[0] !== 1 || orientation[1] || orientation[2] || orientation[3]))
      throw new Refused(`geoms[${i}]: a turned geom: not built here`);
    const geom = { index: i, shape: g.shape, body: g.body, position: g.position || [0, 0, 0],
      radius: g.radius, size: g.size, height: g.shape === 'plane' ? g.plane[3] : 0 };
    geoms.push(geom);
    if (g.body < 0) statics.push(geom);
    else bodies[g.body].geoms.push(geom);
  });
  // Each geom's surface: its pair with the static geoms, else the default.
  for (const g of geoms) {
    let k = defaultSurface;
    for (const st of statics) {
      const key = `${Math.min(g.index, st.index)},${Math.max(g.index, st.index)}`;
      if (pairSurface.has(key)) { k = pairSurface.get(key); break; }
    }
    g.surface = surfaces[k];
  }
  bodies.forEach((b, i) => { if (!b.geoms.length) throw new Refused(`bodies[${i}]: no geom that touches anything: not built here`); });
  const joints = (w.joints || []).map((j, i) => {
    if (j.type !== 'ball' && j.type !== 'hinge') throw new Refused(`joints[${i}]: type '${j.type}': not built here (ball, hinge)`);
    for (const b of [j.body1, j.body2]) {
      if (b < 0) continue;
      const q = bodies[b].orientation;
      if (j.type === 'hinge' && (q[0] !== 1 || q[1] || q[2] || q[3])) throw new Refused(`joints[${i}]: a hinge on a turned body: not built here`);
    }
    return { type: j.type, body1: j.body1, body2: j.body2, anchor: j.anchor, axis: j.axis || [1, 0, 0] };
  });
  for (const [i, e] of (w.events || []).entries()) {
    if (e.drop === undefined) throw new Refused(`events[${i}]: only "drop" events are built here`);
    bodies[e.drop].dropStep = Math.round(e.at / s.step);
  }
  return { step: s.step, gravity: s.gravity, bodies, statics, joints };
}

// A body's point in its own frame (its orientation is the identity where the harness builds joints).
const minus = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
function rotateInverse(q, v) {
  // v turned by the conjugate of the unit quaternion q = [w, x, y, z].
  const [w, x, y, z] = [q[0], -q[1], -q[2], -q[3]];
  const tx = 2 * (y * v[2] - z * v[1]), ty = 2 * (z * v[0] - x * v[2]), tz = 2 * (x * v[1] - y * v[0]);
  return [v[0] + w * tx + (y * tz - z * ty), v[1] + w * ty + (z * tx - x * tz), v[2] + w * tz + (x * ty - y * tx)];
}
function perpendicular(a) {
  const t = Math.abs(a[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
  const c = [a[1] * t[2] - a[2] * t[1], a[2] * t[0] - a[0] * t[2], a[0] * t[1] - a[1] * t[0]];
  const n = Math.hypot(...c);
  return c.map((x) => x / n);
}

// ---- Rapier ---------------------------------------------------------------
async function rapier() {
  const R = require('@dimforge/rapier3d-compat');
  await R.init();
  const v = (a) => ({ x: a[0], y: a[1], z: a[2] });
  return (w) => {
    const world = new R.World(v(w.gravity));
    world.timestep = w.step;
    const ground = world.createRigidBody(R.RigidBodyDesc.fixed());
    for (const g of w.statics) {
      const desc = g.shape === 'plane'
        ? R.ColliderDesc.cuboid(PLANE_SIDE / 2, PLANE_DEPTH / 2, PLANE_SIDE / 2).setTranslation(0, g.height - PLANE_DEPTH / 2, 0)
        : shapeDesc(g).setTranslation(...g.position);
      world.createCollider(desc.setFriction(g.surface.mu).setRestitution(g.surface.restitution), ground);
    }
    function shapeDesc(g) {
      return g.shape === 'sphere' ? R.ColliderDesc.ball(g.radius) : R.ColliderDesc.cuboid(g.size[0] / 2, g.size[1] / 2, g.size[2] / 2);
    }
    const made = w.bodies.map(() => null);
    function add(i) {
      const b = w.bodies[i];
      const q = b.orientation;
      let desc = R.RigidBodyDesc.dynamic().setTranslation(...b.position).setRotation({ w: q[0], x: q[1], y: q[2], z: q[3] })
        .setLinvel(...b.linearVelocity).setAngvel(v(b.angularVelocity))
        .setAdditionalMassProperties(b.mass, v([0, 0, 0]), v(b.inertia), { w: 1, x: 0, y: 0, z: 0 }).setCanSleep(false);
      if (!b.gravity) desc = desc.setGravityScale(0);
      const body = world.createRigidBody(desc);
      for (const g of b.geoms)
        world.createCollider(shapeDesc(g).setTranslation(...g.position).setDensity(0)
          .setFriction(g.surface.mu).setRestitution(g.surface.restitution), body);
      made[i] = body;
    }
    function joints() {
      for (const j of w.joints) {
        const local = (b) => (b < 0 ? j.anchor : rotateInverse(w.bodies[b].orientation, minus(j.anchor, w.bodies[b].position)));
        const one = j.body2 < 0 ? ground : made[j.body2], two = j.body1 < 0 ? ground : made[j.body1];
        const data = j.type === 'ball' ? R.JointData.spherical(v(local(j.body2)), v(local(j.body1)))
          : R.JointData.revolute(v(local(j.body2)), v(local(j.body1)), v(j.axis));
        world.createImpulseJoint(data, one, two, true).setContactsEnabled(false);
      }
    }
    return {
      add, joints,
      step: () => world.step(),
      read: (i, out, at) => {
        const b = made[i];
        const p = b.translation(), q = b.rotation();
        out[at] = p.x; out[at + 1] = p.y; out[at + 2] = p.z;
        out[at + 3] = q.w; out[at + 4] = q.x; out[at + 5] = q.y; out[at + 6] = q.z;
      },
      free: () => world.free(),
    };
  };
}

// ---- Havok ----------------------------------------------------------------
async function havok() {
  const wasmBinary = fs.readFileSync(require.resolve('@babylonjs/havok/lib/umd/HavokPhysics.wasm'));
  const HK = await require('@babylonjs/havok')({ wasmBinary });
  const ok = (result, what) => {
    const status = Array.isArray(result) ? result[0] : result;
    if (status !== HK.Result.RESULT_OK) throw new Error(`Havok: ${what} failed`);
    return Array.isArray(result) ? result[1] : undefined;
  };
  const xyzw = (q) => [q[1], q[2], q[3], q[0]];
  return (w) => {
    const world = ok(HK.HP_World_Create(), 'HP_World_Create');
    ok(HK.HP_World_SetGravity(world, w.gravity), 'HP_World_SetGravity');
    const material = (shape, sf) => ok(HK.HP_Shape_SetMaterial(shape, [sf.mu, sf.mu, sf.restitution,
      HK.MaterialCombine.GEOMETRIC_MEAN, HK.MaterialCombine.MAXIMUM]), 'HP_Shape_SetMaterial');
    const leaf = (g, at) => (g.shape === 'sphere' ? ok(HK.HP_Shape_CreateSphere(at, g.radius), 'HP_Shape_CreateSphere')
      : ok(HK.HP_Shape_CreateBox(at, [0, 0, 0, 1], g.size), 'HP_Shape_CreateBox'));
    const staticBody = (shape, position) => {
      const id = ok(HK.HP_Body_Create(), 'HP_Body_Create');
      if (shape) ok(HK.HP_Body_SetShape(id, shape), 'HP_Body_SetShape');
      ok(HK.HP_Body_SetMotionType(id, HK.MotionType.STATIC), 'HP_Body_SetMotionType');
      ok(HK.HP_Body_SetQTransform(id, [position, [0, 0, 0, 1]]), 'HP_Body_SetQTransform');
      ok(HK.HP_World_AddBody(world, id, false), 'HP_World_AddBody');
      return id;
    };
    for (const g of w.statics) {
      const shape = g.shape === 'plane' ? ok(HK.HP_Shape_CreateBox([0, 0, 0], [0, 0, 0, 1], [PLANE_SIDE, PLANE_DEPTH, PLANE_SIDE]), 'HP_Shape_CreateBox')
        : leaf(g, [0, 0, 0]);
      material(shape, g.surface);
      staticBody(shape, g.shape === 'plane' ? [0, g.height - PLANE_DEPTH / 2, 0] : g.position);
    }
    const anchor = staticBody(null, [0, 0, 0]);
    const made = w.bodies.map(() => null);
    function add(i) {
      const b = w.bodies[i];
      const id = ok(HK.HP_Body_Create(), 'HP_Body_Create');
      let shape;
      if (b.geoms.length === 1) {
        shape = leaf(b.geoms[0], b.geoms[0].position);
        material(shape, b.geoms[0].surface);
      } else {
        shape = ok(HK.HP_Shape_CreateContainer(), 'HP_Shape_CreateContainer');
        for (const g of b.geoms) {
          const child = leaf(g, g.position);
          material(child, g.surface);
          ok(HK.HP_Shape_AddChild(shape, child, [[0, 0, 0], [0, 0, 0, 1], [1, 1, 1]]), 'HP_Shape_AddChild');
        }
      }
      ok(HK.HP_Body_SetShape(id, shape), 'HP_Body_SetShape');
      ok(HK.HP_Body_SetMotionType(id, HK.MotionType.DYNAMIC), 'HP_Body_SetMotionType');
      ok(HK.HP_Body_SetMassProperties(id, [[0, 0, 0], b.mass, b.inertia.map((x) => x / b.mass), [0, 0, 0, 1]]), 'HP_Body_SetMassProperties');
      if (!b.gravity) ok(HK.HP_Body_SetGravityFactor(id, 0), 'HP_Body_SetGravityFactor');
      ok(HK.HP_Body_SetQTransform(id, [b.position, xyzw(b.orientation)]), 'HP_Body_SetQTransform');
      ok(HK.HP_World_AddBody(world, id, false), 'HP_World_AddBody');
      ok(HK.HP_Body_SetLinearVelocity(id, b.linearVelocity), 'HP_Body_SetLinearVelocity');
      ok(HK.HP_Body_SetAngularVelocity(id, b.angularVelocity), 'HP_Body_SetAngularVelocity');
      ok(HK.HP_Body_SetActivationControl(id, HK.ActivationControl.ALWAYS_ACTIVE), 'HP_Body_SetActivationControl');
      made[i] = id;
    }
    function joints() {
      const A = HK.ConstraintAxis;
      for (const j of w.joints) {
        const c = ok(HK.HP_Constraint_Create(), 'HP_Constraint_Create');
        const parent = j.body2 < 0 ? anchor : made[j.body2], child = j.body1 < 0 ? anchor : made[j.body1];
        ok(HK.HP_Constraint_SetParentBody(c, parent), 'HP_Constraint_SetParentBody');
        ok(HK.HP_Constraint_SetChildBody(c, child), 'HP_Constraint_SetChildBody');
        const x = j.axis, y = perpendicular(x);
        const local = (b) => (b < 0 ? j.anchor : rotateInverse(w.bodies[b].orientation, minus(j.anchor, w.bodies[b].position)));
        // The bodies are unturned where a hinge is built, so the axes are the same in both frames.
        ok(HK.HP_Constraint_SetAnchorInParent(c, local(j.body2), x, y), 'HP_Constraint_SetAnchorInParent');
        ok(HK.HP_Constraint_SetAnchorInChild(c, local(j.body1), x, y), 'HP_Constraint_SetAnchorInChild');
        const locked = j.type === 'ball' ? [A.LINEAR_X, A.LINEAR_Y, A.LINEAR_Z] : [A.LINEAR_X, A.LINEAR_Y, A.LINEAR_Z, A.ANGULAR_Y, A.ANGULAR_Z];
        const free = j.type === 'ball' ? [A.ANGULAR_X, A.ANGULAR_Y, A.ANGULAR_Z] : [A.ANGULAR_X];
        for (const axis of locked) ok(HK.HP_Constraint_SetAxisMode(c, axis, HK.ConstraintAxisLimitMode.LOCKED), 'HP_Constraint_SetAxisMode');
        for (const axis of free) ok(HK.HP_Constraint_SetAxisFriction(c, axis, 0), 'HP_Constraint_SetAxisFriction');
        ok(HK.HP_Constraint_SetCollisionsEnabled(c, false), 'HP_Constraint_SetCollisionsEnabled');
        ok(HK.HP_Constraint_SetEnabled(c, true), 'HP_Constraint_SetEnabled');
      }
    }
    const h = w.step;
    return {
      add, joints,
      step: () => HK.HP_World_Step(world, h),
      read: (i, out, at) => {
        const [, [p, q]] = HK.HP_Body_GetQTransform(made[i]);
        out[at] = p[0]; out[at + 1] = p[1]; out[at + 2] = p[2];
        out[at + 3] = q[3]; out[at + 4] = q[0]; out[at + 5] = q[1]; out[at + 6] = q[2];
      },
      // A fresh module per repeat would cost a load; the worlds are few and small.
      free: () => {},
    };
  };
}

// ---- Jolt -----------------------------------------------------------------
async function jolt() {
  const { default: init } = await import('jolt-physics/wasm-compat');
  const J = await init();
  return (w) => {
    const iface = joltInterface(J);
    const system = iface.GetPhysicsSystem();
    const bi = system.GetBodyInterface();
    system.SetGravity(new J.Vec3(...w.gravity));
    const v3 = (a) => new J.Vec3(a[0], a[1], a[2]);
    const staticBody = (shape, position, sf) => {
      const s = new J.BodyCreationSettings(shape, new J.RVec3(...position), new J.Quat(0, 0, 0, 1), J.EMotionType_Static, STATIC);
      if (sf) { s.mFriction = sf.mu; s.mRestitution = sf.restitution; }
      const body = bi.CreateBody(s);
      J.destroy(s);
      bi.AddBody(body.GetID(), J.EActivation_DontActivate);
      return body;
    };
    const leaf = (g) => (g.shape === 'sphere' ? new J.SphereShapeSettings(g.radius)
      : new J.BoxShapeSettings(v3(g.size.map((x) => x / 2)), Math.min(0.05, ...g.size.map((x) => x / 2))));
    for (const g of w.statics) {
      if (g.shape === 'plane') staticBody(new J.PlaneShape(new J.Plane(new J.Vec3(0, 1, 0), -g.height), null, 1000), [0, 0, 0], g.surface);
      else staticBody(leaf(g).Create().Get(), g.position, g.surface);
    }
    let anchor = null;
    const made = w.bodies.map(() => null);
    function add(i) {
      const b = w.bodies[i];
      let shapeSettings;
      const g0 = b.geoms[0];
      if (b.geoms.length === 1 && !g0.position[0] && !g0.position[1] && !g0.position[2]) {
        shapeSettings = leaf(g0);
      } else if (b.geoms.length === 1) {
        shapeSettings = new J.RotatedTranslatedShapeSettings(v3(g0.position), new J.Quat(0, 0, 0, 1), leaf(g0));
      } else {
        shapeSettings = new J.StaticCompoundShapeSettings();
        for (const g of b.geoms) shapeSettings.AddShapeShapeSettings(v3(g.position), new J.Quat(0, 0, 0, 1), leaf(g), 0);
      }
      let shape = shapeSettings.Create().Get();
      // Jolt puts a body's origin at its shape's centre of mass; the world's origin is its own.
      const c = shape.GetCenterOfMass();
      if (c.GetX() || c.GetY() || c.GetZ())
        shape = new J.OffsetCenterOfMassShapeSettings(new J.Vec3(-c.GetX(), -c.GetY(), -c.GetZ()), shapeSettings).Create().Get();
      const q = b.orientation;
      const s = new J.BodyCreationSettings(shape, new J.RVec3(...b.position), new J.Quat(q[1], q[2], q[3], q[0]), J.EMotionType_Dynamic, MOVING);
      s.mOverrideMassProperties = J.EOverrideMassProperties_MassAndInertiaProvided;
      s.mMassPropertiesOverride.mMass = b.mass;
      const inertia = s.mMassPropertiesOverride.mInertia;
      inertia.SetColumn3(0, new J.Vec3(b.inertia[0], 0, 0));
      inertia.SetColumn3(1, new J.Vec3(0, b.inertia[1], 0));
      inertia.SetColumn3(2, new J.Vec3(0, 0, b.inertia[2]));
      s.mFriction = g0.surface.mu;
      s.mRestitution = g0.surface.restitution;
      s.mAllowSleeping = false;
      if (!b.gravity) s.mGravityFactor = 0;
      const body = bi.CreateBody(s);
      J.destroy(s);
      bi.AddBody(body.GetID(), J.EActivation_Activate);
      bi.SetLinearVelocity(body.GetID(), v3(b.linearVelocity));
      bi.SetAngularVelocity(body.GetID(), v3(b.angularVelocity));
      made[i] = body;
    }
    const bodyOf = (i) => {
      if (i >= 0) return made[i];
      if (!anchor) anchor = staticBody(new J.EmptyShape(), [0, 0, 0], null);
      return anchor;
    };
    function joints() {
      for (const j of w.joints) {
        let s;
        if (j.type === 'ball') {
          s = new J.PointConstraintSettings();
          s.mPoint1 = s.mPoint2 = new J.RVec3(...j.anchor);
        } else {
          s = new J.HingeConstraintSettings();
          s.mPoint1 = s.mPoint2 = new J.RVec3(...j.anchor);
          s.mHingeAxis1 = s.mHingeAxis2 = v3(j.axis);
          s.mNormalAxis1 = s.mNormalAxis2 = v3(perpendicular(j.axis));
        }
        system.AddConstraint(s.Create(bodyOf(j.body2), bodyOf(j.body1)));
      }
    }
    const h = w.step;
    return {
      add, joints,
      step: () => iface.Step(h, 1),
      read: (i, out, at) => {
        const b = made[i];
        const p = b.GetPosition(), q = b.GetRotation();
        out[at] = p.GetX(); out[at + 1] = p.GetY(); out[at + 2] = p.GetZ();
        out[at + 3] = q.GetW(); out[at + 4] = q.GetX(); out[at + 5] = q.GetY(); out[at + 6] = q.GetZ();
      },
      free: () => J.destroy(iface),
    };
  };
}

// One repeat: a fresh world, `steps` steps timed one by one.
function run(makeWorld, w, steps) {
  const sim = makeWorld(w);
  const live = [];
  // Drops in time order, so the loop takes them from the front.
  const pending = w.bodies.map((b, i) => i).filter((i) => w.bodies[i].dropStep > 0)
    .sort((a, b) => w.bodies[a].dropStep - w.bodies[b].dropStep);
  w.bodies.forEach((b, i) => { if (b.dropStep <= 0) { sim.add(i); live.push(i); } });
  sim.joints();
  const out = new Float64Array(7 * w.bodies.length);
  let stepped = 0n;
  const start = process.hrtime.bigint();
  for (let n = 0; n < steps; ++n) {
    while (pending.length && w.bodies[pending[0]].dropStep <= n) {
      const i = pending.shift();
      sim.add(i);
      live.push(i);
    }
    const t0 = process.hrtime.bigint();
    sim.step();
    stepped += process.hrtime.bigint() - t0;
    for (let k = 0; k < live.length; ++k) sim.read(live[k], out, 7 * live[k]);
  }
  const loop = Number(process.hrtime.bigint() - start) / 1e9;
  for (const x of out) if (!Number.isFinite(x)) throw new Error('a body\'s state is not finite: the world blew up');
  sim.free();
  const states = w.bodies.map((b, i) => (live.includes(i) ? Array.from(out.subarray(7 * i, 7 * i + 7)) : null));
  return { step: Number(stepped) / 1e9 / steps, loop: loop / steps, bodies: live.length, states };
}

async function main() {
  let options, w;
  try {
    options = parseArgs(process.argv.slice(2));
    w = readWorld(options.world);
  } catch (error) {
    if (!(error instanceof Refused)) throw error;
    process.stderr.write(`bare.js: ${error.message}\n`);
    return 2;
  }
  const makeWorld = await { havok, jolt, rapier }[options.engine]();
  const warm = [];
  for (let r = 0; r < options.warmup; ++r) warm.push(run(makeWorld, w, options.steps));
  const results = [];
  for (let r = 0; r < options.repeats; ++r) results.push(run(makeWorld, w, options.steps));
  const median = (xs) => { const s = [...xs].sort((a, b) => a - b); const k = s.length >> 1; return s.length % 2 ? s[k] : (s[k - 1] + s[k]) / 2; };
  const steps = results.map((x) => x.step);
  process.stdout.write(`${JSON.stringify({
    engine: options.engine, world: path.basename(options.world), steps: options.steps, repeats: options.repeats,
    warmup: options.warmup, bodies: results[0].bodies, cold_step_seconds: warm.length ? warm[0].step : null, step_seconds: median(steps), step_seconds_min: Math.min(...steps),
    step_seconds_max: Math.max(...steps), loop_seconds: median(results.map((x) => x.loop)),
    ...(options.states ? { states: results[results.length - 1].states } : {}),
  })}\n`);
  return 0;
}

main().then((code) => { process.exitCode = code; }, (error) => { process.stderr.write(`bare.js: ${error.stack || error}\n`); process.exitCode = 1; });
