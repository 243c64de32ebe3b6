'use strict';
// Havok (@babylonjs/havok, float32) builds any world the lab describes,
// through its raw HP_ API: one HP_World_Step(h) per fixed step.
//
// How the world maps onto Havok:
// - each geom is one Havok shape with its offset baked in; a body with
//   several geoms holds them in a container; a static geom is a static body;
// - Havok has no plane: a plane is a static box 1000 m across and 10 m deep
//   whose top face lies on it;
// - the mass and the full inertia tensor go in as principal moments (per
//   unit mass, as HP_Body_SetMassProperties takes them) and their axes;
// - each surface per pair becomes per-shape materials and a combine rule
//   (materials.js): Havok has no per-contact hook;
// - every joint is a 6-DOF constraint with the axes it holds locked, its
//   parent the body of ODE's body2 and its child ODE's body1, so that
//   Havok's limits, measured on the child against the parent, read as ODE's
//   hinge angle and slider position (body1 against body2); contacts between
//   the joined bodies are off, as in ODE's programs;
// - a force for one step is the impulse F h at the centre of mass.
// "best": the solver tuned for the world's step (HP_World_SetIdealStepTime,
// by default 1/60 s and rescaled for others), no damping (Havok's default
// angular damping is 0.1) and the speed caps out of reach (200 m/s and
// 100 rad/s by default), so nothing slows a body that ODE would not.
const { StepClock } = require('./clock');
const { World } = require('./world');
const { Notes, fmt } = require('./notes');
const m = require('./math');
const { planMaterial, relevantPairs } = require('./materials');
const { commonNotes, frictionValue, planNotes } = require('./translate');

const PACKAGE = '@babylonjs/havok';
const NO_SPEED_LIMIT = 1e9;
const PLANE_SIDE = 1000, PLANE_DEPTH = 10;
const LARGEST_FRICTION = 1e6;  // mu = infinity (checked: a 5000 kg cube on a 5 kg one holds)
const OPEN_LIMIT = 1e6;        // a stop on one side only: the other far beyond reach
const RULE_NAMES = { min: 'minimum', max: 'maximum', average: 'arithmetic mean', geometric: 'geometric mean', multiply: 'product' };

const xyzw = (q) => [q[1], q[2], q[3], q[0]];
const wxyz = (q) => [q[3], q[0], q[1], q[2]];

function check(result, what) {
  const status = Array.isArray(result) ? result[0] : result;
  if (status !== undefined && status.value !== undefined && status.value !== 0) throw new Error(`Havok: ${what} failed`);
  return Array.isArray(result) ? result[1] : undefined;
}

class HavokEngine {
  constructor(HK, best) {
    this.HK = HK;
    this.best = best;
    this.notes = new Notes();
    this.bodies = [];     // per body index: { id, joints: [constraint ids] } or null once removed
    this.shapes = [];     // per geom index: the leaf shape, or null
    this.statics = [];    // static bodies of static geoms
    this.anchor = null;   // a static body with no shape: "the world" for joints
    this.removedSet = new Set();
    this.clock = new StepClock();
  }

  build(json, removed = []) {
    const HK = this.HK;
    for (const r of removed) this.removedSet.add(r);
    this.world = new World(json, [...this.removedSet]);
    this.id = check(HK.HP_World_Create(), 'HP_World_Create');
    const [, linearCap, angularCap] = HK.HP_World_GetSpeedLimit(this.id);
    this.defaultCaps = [linearCap, angularCap];
    this.applySettings();
    this.anchor = check(HK.HP_Body_Create(), 'HP_Body_Create');
    check(HK.HP_Body_SetMotionType(this.anchor, HK.MotionType.STATIC), 'HP_Body_SetMotionType');
    check(HK.HP_World_AddBody(this.id, this.anchor, false), 'HP_World_AddBody');
    this.addFrom(0, 0, 0);
  }

  add(json, firstBody, firstGeom, firstJoint) {
    this.world = new World(json, [...this.removedSet]);
    this.addFrom(firstBody, firstGeom, firstJoint);
  }

  applySettings() {
    const HK = this.HK, w = this.world, s = w.settings;
    this.h = s.step;
    check(HK.HP_World_SetGravity(this.id, s.gravity), 'HP_World_SetGravity');
    if (this.best) {
      check(HK.HP_World_SetIdealStepTime(this.id, this.h), 'HP_World_SetIdealStepTime');
    } else if (Math.abs(this.h - 1 / 60) > 1e-12) {
      this.notes.add(`Havok's solver is tuned for a step of 1/60 s and rescales its stiffness for the world's ${fmt(this.h)} s (its default; best tunes it for the step)`);
    }
    // Speed caps: the world's own angular cap where every body shares one
    // (Havok has one per world), else out of reach in best, Havok's in default.
    const capped = w.bodies.filter((b, i) => !w.removed.has(i) && b.maxAngularSpeed !== Infinity).map((b) => b.maxAngularSpeed);
    const shared = capped.length && capped.every((c) => c === capped[0]) && capped.length === w.bodies.length ? capped[0] : null;
    if (capped.length && shared === null)
      this.notes.add(`Havok has one angular speed cap per world: the bodies' max_angular_speed (${fmt(capped[0])} rad/s on some) is not applied`);
    let [linear, angular] = this.defaultCaps;
    if (this.best) linear = angular = NO_SPEED_LIMIT;
    else this.notes.add(`Havok caps every body's speed at ${fmt(linear)} m/s and ${fmt(angular)} rad/s (its defaults; best raises them out of reach)`);
    if (shared !== null) angular = shared;
    check(HK.HP_World_SetSpeedLimit(this.id, linear, angular), 'HP_World_SetSpeedLimit');
    commonNotes(w, this.notes, 'Havok', { maxAngularSpeed: true });
  }

  // A geom's shape; `pose`: its offset on its body ([position, [w,x,y,z]]) or none (static).
  leafShape(g, offset) {
    const HK = this.HK;
    const [p, q] = offset;
    switch (g.shape) {
      case 'box':
        return check(HK.HP_Shape_CreateBox(p, xyzw(q), g.size), 'HP_Shape_CreateBox');
      case 'sphere':
        return check(HK.HP_Shape_CreateSphere(p, g.size[0]), 'HP_Shape_CreateSphere');
      case 'capsule':
      case 'cylinder': {
        const half = m.rotate(q, [0, 0, g.size[1] / 2]);
        const create = g.shape === 'capsule' ? 'HP_Shape_CreateCapsule' : 'HP_Shape_CreateCylinder';
        return check(HK[create](m.sub(p, half), m.add(p, half), g.size[0]), create);
      }
      case 'plane': {
        this.notes.add(`Havok has no plane: each plane became a static box ${PLANE_SIDE} m across and ${PLANE_DEPTH} m deep, its top face on the plane`);
        return check(HK.HP_Shape_CreateBox([0, 0, 0], [0, 0, 0, 1], [PLANE_SIDE, PLANE_DEPTH, PLANE_SIDE]), 'HP_Shape_CreateBox');
      }
      default:
        throw new Error(`Havok: no shape '${g.shape}'`);
    }
  }

  // The world pose of a static geom's body (a plane's box below its surface).
  staticPose(g) {
    if (g.shape !== 'plane') return [g.position, g.orientation];
    const n = m.unit(g.plane.slice(0, 3));
    const q = m.frameFrom(n);  // x along n ...
    const yUp = m.qmul(q, [Math.SQRT1_2, 0, 0, -Math.SQRT1_2]);  // ... turned so the box's y is n
    return [m.scale(n, g.plane[3] - PLANE_DEPTH / 2), yUp];
  }

  addFrom(firstBody, firstGeom, firstJoint) {
    const HK = this.HK, w = this.world;
    for (let g = firstGeom; g < w.geoms.length; ++g) {
      const geom = w.geoms[g];
      if (geom.body >= 0 && w.removed.has(geom.body)) { this.shapes[g] = null; continue; }
      const offset = geom.body >= 0 ? [geom.position, geom.orientation] : [[0, 0, 0], [1, 0, 0, 0]];
      this.shapes[g] = this.leafShape(geom, offset);
      if (geom.category !== 0xffffffff || geom.collide !== 0xffffffff)
        check(HK.HP_Shape_SetFilterInfo(this.shapes[g], [geom.category, geom.collide]), 'HP_Shape_SetFilterInfo');
      if (geom.body < 0) {
        const id = check(HK.HP_Body_Create(), 'HP_Body_Create');
        check(HK.HP_Body_SetShape(id, this.shapes[g]), 'HP_Body_SetShape');
        check(HK.HP_Body_SetMotionType(id, HK.MotionType.STATIC), 'HP_Body_SetMotionType');
        const [p, q] = this.staticPose(geom);
        check(HK.HP_Body_SetQTransform(id, [p, xyzw(q)]), 'HP_Body_SetQTransform');
        check(HK.HP_World_AddBody(this.id, id, false), 'HP_World_AddBody');
        this.statics.push(id);
      }
    }
    for (let b = firstBody; b < w.bodies.length; ++b) this.bodies[b] = w.removed.has(b) ? null : this.makeBody(b);
    this.collideBitNotes();
    this.applyMaterials();
    for (let j = firstJoint; j < w.joints.length; ++j) this.makeJoint(w.joints[j]);
  }

  makeBody(index) {
    const HK = this.HK, body = this.world.bodies[index];
    const id = check(HK.HP_Body_Create(), 'HP_Body_Create');
    const geoms = this.world.geomsOf(index);
    if (geoms.length === 1) {
      check(HK.HP_Body_SetShape(id, this.shapes[geoms[0]]), 'HP_Body_SetShape');
    } else if (geoms.length > 1) {
      const container = check(HK.HP_Shape_CreateContainer(), 'HP_Shape_CreateContainer');
      (this.containers = this.containers || []).push(container);
      for (const g of geoms)
        check(HK.HP_Shape_AddChild(container, this.shapes[g], [[0, 0, 0], [0, 0, 0, 1], [1, 1, 1]]), 'HP_Shape_AddChild');
      check(HK.HP_Body_SetShape(id, container), 'HP_Body_SetShape');
    }
    check(HK.HP_Body_SetMotionType(id, body.kinematic ? HK.MotionType.KINEMATIC : HK.MotionType.DYNAMIC), 'HP_Body_SetMotionType');
    const { moments, rotation } = m.principalInertia(body.inertia);
    check(HK.HP_Body_SetMassProperties(id, [[0, 0, 0], body.mass, moments.map((i) => i / body.mass), xyzw(rotation)]),
      'HP_Body_SetMassProperties');
    const linearDamping = HK.HP_Body_GetLinearDamping(id)[1], angularDamping = HK.HP_Body_GetAngularDamping(id)[1];
    if (this.best) {
      check(HK.HP_Body_SetLinearDamping(id, 0), 'HP_Body_SetLinearDamping');
      check(HK.HP_Body_SetAngularDamping(id, 0), 'HP_Body_SetAngularDamping');
    } else if (linearDamping || angularDamping) {
      this.notes.add(`Havok damps every body by default (linear ${fmt(linearDamping)}, angular ${fmt(angularDamping)}); the world has no damping (best sets it to 0)`);
    }
    if (!body.gravity) check(HK.HP_Body_SetGravityFactor(id, 0), 'HP_Body_SetGravityFactor');
    check(HK.HP_Body_SetQTransform(id, [body.position, xyzw(body.orientation)]), 'HP_Body_SetQTransform');
    check(HK.HP_World_AddBody(this.id, id, !body.enabled && body.autoDisable.on), 'HP_World_AddBody');
    check(HK.HP_Body_SetLinearVelocity(id, body.linearVelocity), 'HP_Body_SetLinearVelocity');
    check(HK.HP_Body_SetAngularVelocity(id, body.angularVelocity), 'HP_Body_SetAngularVelocity');
    // ODE's auto-disable becomes Havok's own sleeping (its thresholds are not exposed); a body without it never sleeps.
    if (body.autoDisable.on) {
      check(HK.HP_Body_SetActivationControl(id, HK.ActivationControl.SIMULATION_CONTROLLED), 'HP_Body_SetActivationControl');
      this.notes.add("ODE's auto-disable became Havok's own sleeping, whose thresholds cannot be set: the world's are not applied");
    } else {
      check(HK.HP_Body_SetActivationControl(id, HK.ActivationControl.ALWAYS_ACTIVE), 'HP_Body_SetActivationControl');
      if (!body.enabled) this.notes.add('a body exported asleep without auto-disable starts awake in Havok');
    }
    return { id, joints: [] };
  }

  // Havok's filter keeps two shapes apart unless each one's membership meets
  // the other's mask; ODE lets them touch when either does.
  collideBitNotes() {
    const w = this.world;
    if (!w.hasCollideBits()) return;
    const odd = [];
    w.geoms.forEach((g, i) => { if (g.category !== 0xffffffff || g.collide !== 0xffffffff) odd.push(i); });
    for (const a of odd)
      for (let b = 0; b < w.geoms.length; ++b) {
        if (b === a || !this.shapes[a] || !this.shapes[b]) continue;
        const ga = w.geoms[a], gb = w.geoms[b];
        const both = ((ga.category & gb.collide) >>> 0) !== 0 && ((gb.category & ga.collide) >>> 0) !== 0;
        if (both !== w.bitsTouch(a, b) && (ga.body >= 0 || gb.body >= 0) && ga.body !== gb.body) {
          this.notes.add(`collide bits: Havok lets two shapes touch only when each one's category meets the other's collide bits (ODE: either), so geoms ${Math.min(a, b)} and ${Math.max(a, b)} do not touch`);
          return;
        }
      }
  }

  applyMaterials() {
    const HK = this.HK, w = this.world;
    const built = [];
    this.shapes.forEach((s, g) => { if (s) built.push(g); });
    const cache = relevantPairs(w, built);
    const rules = ['geometric', 'min', 'max', 'average', 'multiply'];
    const friction = planMaterial(w, built, (s) => frictionValue(s.mu, LARGEST_FRICTION, this.notes, 'Havok'), rules, cache);
    const restitution = planMaterial(w, built, (s) => (s.bounce ? s.restitution : 0), rules, cache);
    const name = (r) => RULE_NAMES[r];
    planNotes(friction, 'friction', 'Havok', this.notes, name);
    planNotes(restitution, 'restitution', 'Havok', this.notes, name);
    const mode = { geometric: 'GEOMETRIC_MEAN', min: 'MINIMUM', max: 'MAXIMUM', average: 'ARITHMETIC_MEAN', multiply: 'MULTIPLY' };
    for (const g of built) {
      const mu = friction.value(g);
      check(HK.HP_Shape_SetMaterial(this.shapes[g], [mu, mu, restitution.value(g), HK.MaterialCombine[mode[friction.rule]],
        HK.MaterialCombine[mode[restitution.rule]]]), 'HP_Shape_SetMaterial');
    }
  }

  bodyId(index) {
    return index < 0 ? this.anchor : this.bodies[index].id;
  }

  // A pose in a body's frame (the anchor's frame is the world's).
  toLocal(index, point, direction) {
    if (index < 0) return [point, direction];
    const [[p, q]] = [this.transform(index)];
    const inv = m.qconj(q);
    return [m.rotate(inv, m.sub(point, p)), direction.map((d) => m.rotate(inv, d))];
  }

  transform(index) {
    const [pos, rot] = check(this.HK.HP_Body_GetQTransform(this.bodies[index].id), 'HP_Body_GetQTransform');
    return [pos, wxyz(rot)];
  }

  makeJoint(joint) {
    const HK = this.HK, A = HK.ConstraintAxis, L = HK.ConstraintAxisLimitMode;
    if ((joint.body1 >= 0 && !this.bodies[joint.body1]) || (joint.body2 >= 0 && !this.bodies[joint.body2])) return;
    const parent = joint.body2, child = joint.body1;
    const c = check(HK.HP_Constraint_Create(), 'HP_Constraint_Create');
    check(HK.HP_Constraint_SetParentBody(c, this.bodyId(parent)), 'HP_Constraint_SetParentBody');
    check(HK.HP_Constraint_SetChildBody(c, this.bodyId(child)), 'HP_Constraint_SetChildBody');
    // The pivot: the anchor (ball, hinge), else the child's centre (slider, fixed).
    const childCentre = child >= 0 ? this.transform(child)[0] : (parent >= 0 ? this.transform(parent)[0] : [0, 0, 0]);
    const pivot = joint.type === 'ball' || joint.type === 'hinge' ? joint.anchor : childCentre;
    const x = m.unit(joint.axis), y = m.perpendicular(x);
    const [pp, [px, py]] = this.toLocal(parent, pivot, [x, y]);
    const [cp, [cx, cy]] = this.toLocal(child, pivot, [x, y]);
    check(HK.HP_Constraint_SetAnchorInParent(c, pp, px, py), 'HP_Constraint_SetAnchorInParent');
    check(HK.HP_Constraint_SetAnchorInChild(c, cp, cx, cy), 'HP_Constraint_SetAnchorInChild');
    const locked = { ball: [A.LINEAR_X, A.LINEAR_Y, A.LINEAR_Z], hinge: [A.LINEAR_X, A.LINEAR_Y, A.LINEAR_Z, A.ANGULAR_Y, A.ANGULAR_Z],
      slider: [A.LINEAR_Y, A.LINEAR_Z, A.ANGULAR_X, A.ANGULAR_Y, A.ANGULAR_Z],
      fixed: [A.LINEAR_X, A.LINEAR_Y, A.LINEAR_Z, A.ANGULAR_X, A.ANGULAR_Y, A.ANGULAR_Z] }[joint.type];
    if (!locked) throw new Error(`Havok: no joint type '${joint.type}'`);
    for (const axis of locked) check(HK.HP_Constraint_SetAxisMode(c, axis, L.LOCKED), 'HP_Constraint_SetAxisMode');
    // The axes a joint leaves free turn without friction (ODE's joints have none).
    const freeAxes = { ball: [A.ANGULAR_X, A.ANGULAR_Y, A.ANGULAR_Z], hinge: [A.ANGULAR_X], slider: [A.LINEAR_X], fixed: [] }[joint.type];
    for (const axis of freeAxes) check(HK.HP_Constraint_SetAxisFriction(c, axis, 0), 'HP_Constraint_SetAxisFriction');
    const free = { hinge: A.ANGULAR_X, slider: A.LINEAR_X }[joint.type];
    if (free !== undefined && (joint.lowStop !== -Infinity || joint.highStop !== Infinity)) {
      check(HK.HP_Constraint_SetAxisMode(c, free, L.LIMITED), 'HP_Constraint_SetAxisMode');
      check(HK.HP_Constraint_SetAxisMinLimit(c, free, Math.max(joint.lowStop, -OPEN_LIMIT)), 'HP_Constraint_SetAxisMinLimit');
      check(HK.HP_Constraint_SetAxisMaxLimit(c, free, Math.min(joint.highStop, OPEN_LIMIT)), 'HP_Constraint_SetAxisMaxLimit');
    }
    check(HK.HP_Constraint_SetCollisionsEnabled(c, false), 'HP_Constraint_SetCollisionsEnabled');
    check(HK.HP_Constraint_SetEnabled(c, true), 'HP_Constraint_SetEnabled');
    for (const b of [joint.body1, joint.body2]) if (b >= 0) this.bodies[b].joints.push(c);
  }

  // The end of a session, or a fresh engine taking over ('reset'):
  // every constraint, body, shape and the world given
  // back to the module, which a page shares between sessions.
  dispose() {
    const HK = this.HK;
    if (this.id === undefined || this.id === null) return;
    const constraints = new Set();
    for (const body of this.bodies) if (body) for (const c of body.joints) constraints.add(c);
    for (const c of constraints) HK.HP_Constraint_Release(c);
    const bodyIds = [...this.bodies.filter(Boolean).map((b) => b.id), ...this.statics, this.anchor].filter((id) => id);
    for (const id of bodyIds) {
      HK.HP_World_RemoveBody(this.id, id);
      HK.HP_Body_Release(id);
    }
    for (const shape of this.shapes) if (shape) HK.HP_Shape_Release(shape);
    for (const shape of this.containers || []) HK.HP_Shape_Release(shape);
    HK.HP_World_Release(this.id);
    this.id = null;
    this.bodies = [];
    this.statics = [];
    this.shapes = [];
    this.containers = [];
    this.anchor = null;
  }

  remove(index) {
    const HK = this.HK, body = this.bodies[index];
    if (!body) return;
    for (const c of body.joints) {
      HK.HP_Constraint_SetEnabled(c, false);
      HK.HP_Constraint_Release(c);
    }
    for (const other of this.bodies) if (other) other.joints = other.joints.filter((c) => !body.joints.includes(c));
    check(HK.HP_World_RemoveBody(this.id, body.id), 'HP_World_RemoveBody');
    this.bodies[index] = null;
    this.removedSet.add(index);
  }

  setState(index, s) {
    const HK = this.HK, body = this.bodies[index];
    if (!body) return;
    check(HK.HP_Body_SetQTransform(body.id, [s.slice(0, 3), xyzw(s.slice(3, 7))]), 'HP_Body_SetQTransform');
    check(HK.HP_Body_SetLinearVelocity(body.id, s.slice(7, 10)), 'HP_Body_SetLinearVelocity');
    check(HK.HP_Body_SetAngularVelocity(body.id, s.slice(10, 13)), 'HP_Body_SetAngularVelocity');
    const asleep = s.length > 13 && !s[13];
    HK.HP_Body_SetActivationState(body.id, asleep ? HK.ActivationState.INACTIVE : HK.ActivationState.ACTIVE);
  }

  // A force for one step: the impulse it gives over h, at the centre of mass.
  applyForce(index, force, torque) {
    const HK = this.HK, body = this.bodies[index];
    if (!body) return;
    const centre = this.transform(index)[0];
    check(HK.HP_Body_ApplyImpulse(body.id, centre, m.scale(force, this.h)), 'HP_Body_ApplyImpulse');
    check(HK.HP_Body_ApplyAngularImpulse(body.id, m.scale(torque, this.h)), 'HP_Body_ApplyAngularImpulse');
  }

  changeSettings(json) {
    this.world = new World(json, [...this.removedSet]);
    this.applySettings();
    this.applyMaterials();
  }

  step() {
    this.clock.time(() => this.HK.HP_World_Step(this.id, this.h));
  }

  state(index) {
    const HK = this.HK, body = this.bodies[index];
    if (!body) return null;
    const [p, q] = this.transform(index);
    const v = HK.HP_Body_GetLinearVelocity(body.id)[1], w = HK.HP_Body_GetAngularVelocity(body.id)[1];
    const active = HK.HP_Body_GetActivationState(body.id)[1] === HK.ActivationState.ACTIVE;
    return [...p, ...q, ...v, ...w, active ? 1 : 0];
  }

  contactCount() {
    return -1;  // Havok reports contacts only as events per body, not counted here
  }

  wallSeconds() {
    return this.clock.wallSeconds();
  }

  cpuSeconds() {
    return this.clock.cpuSeconds();
  }
}

// The WebAssembly module, loaded once per process or page. Havok's build
// reads its .wasm file beside it; the host hands over its bytes
// (`wasmBinary`: Node reads WASM_FILE, a page fetches it).
const WASM_FILE = `${PACKAGE}/lib/umd/HavokPhysics.wasm`;
function load({ wasmBinary }) {
  return require('@babylonjs/havok')({ wasmBinary });
}

// One engine (one Havok world at a time) on a loaded module.
const make = (HK, setting) => new HavokEngine(HK, setting === 'best');

module.exports = { load, make, wasmFile: WASM_FILE, packageName: PACKAGE, precision: 'float32' };
