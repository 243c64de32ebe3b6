'use strict';
// Rapier (@dimforge/rapier3d-compat, float32) builds any world the lab
// describes: one world.step() per fixed step with world.timestep = h.
//
// How the world maps onto Rapier:
// - each geom is one collider on its body's rigid body at its offset; the
//   static geoms are colliders of one fixed body; a plane is a large cuboid
//   (the JS API has no half-space);
// - capsules and cylinders lie along y in Rapier, along z in ODE: turned;
// - the mass and the full inertia tensor are the body's additional mass
//   properties (principal moments and their frame), its colliders massless;
// - each surface per pair becomes per-collider friction and restitution
//   and one combine rule (materials.js): the JS API has no per-contact hook
//   that may change a contact's coefficients;
// - ODE's collide bits are a contact-pair filter hook (Rapier's own groups
//   have 16 bits, ODE's 32); joined bodies do not touch (the joint's
//   contacts off), as in ODE's programs;
// - each joint is an impulse joint, its first body ODE's body2 (or the
//   world) and its second ODE's body1, so that its angle and position are
//   ODE's (body1 against body2);
// - a force and a torque for one step are added before the step and both
//   reset after it: Rapier's user forces and torques persist until reset,
//   and resetForces leaves the torques (a drag's torque kept spinning the
//   body after the drag was released).
// "best": 50 solver iterations (default 4), continuous collision (CCD) on
// every moving body (Rapier sweeps only those that move far in a step), and
// the speed cap (400 m/s times lengthUnit) moved out of reach by a
// lengthUnit of 1000 with the two length tolerances the JS API exposes
// divided by as much, so that in metres they stay Rapier's defaults.
const { StepClock } = require('./clock');
const { World } = require('./world');
const { Notes, fmt } = require('./notes');
const m = require('./math');
const { planMaterial, relevantPairs } = require('./materials');
const { commonNotes, frictionValue, planNotes } = require('./translate');

const PACKAGE = '@dimforge/rapier3d-compat';
const BEST_ITERATIONS = 50;
const FAST_LENGTH_UNIT = 1000;
const SPEED_CAP_PER_LENGTH_UNIT = 400;  // m/s (PEERS.md, found by testing)
const LARGEST_FRICTION = 1e6;
const PLANE_SIDE = 1000, PLANE_DEPTH = 10;
const RULE_NAMES = { min: 'minimum', max: 'maximum', average: 'average', multiply: 'product' };

const vec = (a) => ({ x: a[0], y: a[1], z: a[2] });
const rot = (q) => ({ w: q[0], x: q[1], y: q[2], z: q[3] });

class RapierEngine {
  constructor(R, best) {
    this.R = R;
    this.best = best;
    this.notes = new Notes();
    this.bodies = [];      // per body index: the rigid body, or null once removed
    this.colliders = [];   // per geom index: the collider, or null
    this.geomOf = new Map();  // collider handle -> geom index
    this.forced = new Set();  // bodies with a force to reset after the step
    this.removedSet = new Set();
    this.clock = new StepClock();
  }

  // The end of a session, or a fresh engine taking over ('reset'):
  // the world (its bodies, colliders and joints with
  // it) given back to the module, which a page shares between sessions.
  dispose() {
    if (!this.rapier) return;
    this.rapier.free();
    this.rapier = null;
  }

  build(json, removed = []) {
    const R = this.R;
    for (const r of removed) this.removedSet.add(r);
    this.world = new World(json, [...this.removedSet]);
    this.rapier = new R.World(vec(this.world.settings.gravity));
    this.ground = this.rapier.createRigidBody(R.RigidBodyDesc.fixed());
    if (this.best) {
      const p = this.rapier.integrationParameters;
      const error = p.normalizedAllowedLinearError, prediction = p.normalizedPredictionDistance;
      this.rapier.lengthUnit = FAST_LENGTH_UNIT;
      p.normalizedAllowedLinearError = error / FAST_LENGTH_UNIT;
      p.normalizedPredictionDistance = prediction / FAST_LENGTH_UNIT;
    } else {
      this.notes.add(`Rapier caps every body's speed at ${SPEED_CAP_PER_LENGTH_UNIT} m/s (400 times its lengthUnit 1; best raises it)`);
    }
    this.applySettings();
    this.addFrom(0, 0, 0);
  }

  add(json, firstBody, firstGeom, firstJoint) {
    this.world = new World(json, [...this.removedSet]);
    this.addFrom(firstBody, firstGeom, firstJoint);
  }

  applySettings() {
    const w = this.world, s = w.settings;
    this.h = s.step;
    this.rapier.timestep = s.step;
    this.rapier.gravity = vec(s.gravity);
    if (this.best) this.rapier.numSolverIterations = BEST_ITERATIONS;
    this.notes.add(`Rapier solves with ${this.rapier.numSolverIterations} iterations, not the world's ${s.iterations} QuickStep iterations`);
    commonNotes(w, this.notes, 'Rapier', { iterations: true });
    this.hooks = w.hasCollideBits() ? {
      filterContactPair: (c1, c2) => (w.mayTouch(this.geomOf.get(c1), this.geomOf.get(c2)) ? this.R.SolverFlags.COMPUTE_IMPULSE : null),
      filterIntersectionPair: () => true,
    } : undefined;
    // The JS binding calls the hooks only when the step is given an event
    // queue (seen: none without one); it drains itself.
    if (this.hooks && !this.events) this.events = new this.R.EventQueue(true);
  }

  colliderDesc(g) {
    const R = this.R;
    switch (g.shape) {
      case 'box':
        return R.ColliderDesc.cuboid(g.size[0] / 2, g.size[1] / 2, g.size[2] / 2);
      case 'sphere':
        return R.ColliderDesc.ball(g.size[0]);
      case 'capsule':
        return R.ColliderDesc.capsule(g.size[1] / 2, g.size[0]);
      case 'cylinder':
        return R.ColliderDesc.cylinder(g.size[1] / 2, g.size[0]);
      case 'plane':
        this.notes.add(`Rapier's JS API has no half-space: each plane became a static box ${PLANE_SIDE} m across and ${PLANE_DEPTH} m deep, its top face on the plane`);
        return R.ColliderDesc.cuboid(PLANE_SIDE / 2, PLANE_DEPTH / 2, PLANE_SIDE / 2);
      default:
        throw new Error(`Rapier: no shape '${g.shape}'`);
    }
  }

  // A geom's pose on its body (a static geom's in the world).
  static pose(g) {
    if (g.shape === 'plane') {
      const n = m.unit(g.plane.slice(0, 3));
      const yUp = m.qmul(m.frameFrom(n), [Math.SQRT1_2, 0, 0, -Math.SQRT1_2]);
      return [m.scale(n, g.plane[3] - PLANE_DEPTH / 2), yUp];
    }
    const turned = g.shape === 'capsule' || g.shape === 'cylinder' ? m.qmul(g.orientation, m.Y_TO_Z) : g.orientation;
    return [g.position, turned];
  }

  addFrom(firstBody, firstGeom, firstJoint) {
    const R = this.R, w = this.world;
    for (let b = firstBody; b < w.bodies.length; ++b) this.bodies[b] = w.removed.has(b) ? null : this.makeBody(b);
    for (let g = firstGeom; g < w.geoms.length; ++g) {
      const geom = w.geoms[g];
      const parent = geom.body >= 0 ? this.bodies[geom.body] : this.ground;
      if (!parent) { this.colliders[g] = null; continue; }
      const [p, q] = RapierEngine.pose(geom);
      let desc = this.colliderDesc(geom).setTranslation(p[0], p[1], p[2]).setRotation(rot(q)).setDensity(0);
      if (w.hasCollideBits()) desc = desc.setActiveHooks(R.ActiveHooks.FILTER_CONTACT_PAIRS);
      const collider = this.rapier.createCollider(desc, parent);
      this.colliders[g] = collider;
      this.geomOf.set(collider.handle, g);
    }
    this.applyMaterials();
    for (let j = firstJoint; j < w.joints.length; ++j) this.makeJoint(w.joints[j]);
  }

  makeBody(index) {
    const R = this.R, body = this.world.bodies[index];
    const { moments, rotation } = m.principalInertia(body.inertia);
    let desc = (body.kinematic ? R.RigidBodyDesc.kinematicVelocityBased() : R.RigidBodyDesc.dynamic())
      .setTranslation(...body.position).setRotation(rot(body.orientation))
      .setLinvel(...body.linearVelocity).setAngvel(vec(body.angularVelocity))
      .setAdditionalMassProperties(body.mass, vec([0, 0, 0]), vec(moments), rot(rotation))
      .setCanSleep(body.autoDisable.on);
    if (!body.gravity) desc = desc.setGravityScale(0);
    if (!body.enabled && body.autoDisable.on) desc = desc.setSleeping(true);
    if (!body.enabled && !body.autoDisable.on) this.notes.add('a body exported asleep without auto-disable starts awake in Rapier');
    if (body.autoDisable.on) this.notes.add("ODE's auto-disable became Rapier's own sleeping, whose thresholds the JS API does not expose: the world's are not applied");
    if (this.best) desc = desc.setCcdEnabled(true);
    return this.rapier.createRigidBody(desc);
  }

  applyMaterials() {
    const R = this.R, w = this.world;
    const built = [];
    this.colliders.forEach((c, g) => { if (c) built.push(g); });
    const cache = relevantPairs(w, built);
    const rules = ['average', 'min', 'max', 'multiply'];
    const friction = planMaterial(w, built, (s) => frictionValue(s.mu, LARGEST_FRICTION, this.notes, 'Rapier'), rules, cache);
    const restitution = planMaterial(w, built, (s) => (s.bounce ? s.restitution : 0), rules, cache);
    const name = (r) => RULE_NAMES[r];
    planNotes(friction, 'friction', 'Rapier', this.notes, name);
    planNotes(restitution, 'restitution', 'Rapier', this.notes, name);
    const rule = { average: R.CoefficientCombineRule.Average, min: R.CoefficientCombineRule.Min,
      max: R.CoefficientCombineRule.Max, multiply: R.CoefficientCombineRule.Multiply };
    for (const g of built) {
      const c = this.colliders[g];
      c.setFriction(friction.value(g));
      c.setFrictionCombineRule(rule[friction.rule]);
      c.setRestitution(restitution.value(g));
      c.setRestitutionCombineRule(rule[restitution.rule]);
    }
  }

  bodyOf(index) {
    return index < 0 ? this.ground : this.bodies[index];
  }

  // A world point and direction in a body's frame.
  local(index, point, direction) {
    const b = this.bodyOf(index);
    const t = b.translation(), r = b.rotation();
    const inv = m.qconj([r.w, r.x, r.y, r.z]);
    return [m.rotate(inv, m.sub(point, [t.x, t.y, t.z])), direction && m.rotate(inv, direction)];
  }

  makeJoint(joint) {
    const R = this.R;
    if ((joint.body1 >= 0 && !this.bodies[joint.body1]) || (joint.body2 >= 0 && !this.bodies[joint.body2])) return;
    const first = joint.body2, second = joint.body1;
    const axis = m.unit(joint.axis);
    const centreOf = (i) => { const t = this.bodyOf(i).translation(); return [t.x, t.y, t.z]; };
    const at = joint.type === 'ball' || joint.type === 'hinge' ? joint.anchor : centreOf(second >= 0 ? second : first);
    const [a1, x1] = this.local(first, at, axis);
    const [a2, x2] = this.local(second, at, axis);
    let data;
    switch (joint.type) {
      case 'ball':
        data = R.JointData.spherical(vec(a1), vec(a2));
        break;
      case 'hinge':
        data = R.JointData.revoluteWithAxes(vec(a1), vec(a2), vec(x1), vec(x2));
        break;
      case 'slider':
        if (m.norm(m.sub(x1, x2)) > 1e-9)
          this.notes.add("Rapier's JS prismatic joint takes one axis in both bodies' frames: a slider between bodies turned differently slides along the first body's axis");
        data = R.JointData.prismatic(vec(a1), vec(a2), vec(x1));
        break;
      case 'fixed': {
        const q = (i) => { const r = this.bodyOf(i).rotation(); return m.qconj([r.w, r.x, r.y, r.z]); };
        data = R.JointData.fixed(vec(a1), rot(q(first)), vec(a2), rot(q(second)));
        break;
      }
      default:
        throw new Error(`Rapier: no joint type '${joint.type}'`);
    }
    const created = this.rapier.createImpulseJoint(data, this.bodyOf(first), this.bodyOf(second), true);
    created.setContactsEnabled(false);
    if ((joint.type === 'hinge' || joint.type === 'slider') && (joint.lowStop !== -Infinity || joint.highStop !== Infinity))
      created.setLimits(Math.max(joint.lowStop, -1e9), Math.min(joint.highStop, 1e9));
  }

  remove(index) {
    const body = this.bodies[index];
    if (!body) return;
    this.world.geoms.forEach((g, i) => {
      if (g.body === index && this.colliders[i]) {
        this.geomOf.delete(this.colliders[i].handle);
        this.colliders[i] = null;
      }
    });
    this.rapier.removeRigidBody(body);  // its colliders and joints go with it
    this.bodies[index] = null;
    this.forced.delete(index);
    this.removedSet.add(index);
  }

  setState(index, s) {
    const b = this.bodies[index];
    if (!b) return;
    b.setTranslation(vec(s), true);
    b.setRotation(rot(s.slice(3, 7)), true);
    b.setLinvel(vec(s.slice(7, 10)), true);
    b.setAngvel(vec(s.slice(10, 13)), true);
    if (s.length > 13 && !s[13]) b.sleep();
  }

  applyForce(index, force, torque) {
    const b = this.bodies[index];
    if (!b) return;
    b.addForce(vec(force), true);
    b.addTorque(vec(torque), true);
    this.forced.add(index);
  }

  changeSettings(json) {
    this.world = new World(json, [...this.removedSet]);
    this.applySettings();
    this.applyMaterials();
  }

  step() {
    this.clock.time(() => this.rapier.step(this.hooks && this.events, this.hooks));
    for (const i of this.forced) {
      const b = this.bodies[i];
      if (!b) continue;
      b.resetForces(false);
      b.resetTorques(false);
    }
    this.forced.clear();
  }

  state(index) {
    const b = this.bodies[index];
    if (!b) return null;
    const p = b.translation(), q = b.rotation(), v = b.linvel(), w = b.angvel();
    return [p.x, p.y, p.z, q.w, q.x, q.y, q.z, v.x, v.y, v.z, w.x, w.y, w.z, b.isSleeping() ? 0 : 1];
  }

  contactCount() {
    return -1;  // the JS API counts contacts only pair by pair; not counted here
  }

  wallSeconds() {
    return this.clock.wallSeconds();
  }

  cpuSeconds() {
    return this.clock.cpuSeconds();
  }
}

// The WebAssembly module (inlined in the compat package), loaded once per
// process or page.
async function load() {
  const R = require('@dimforge/rapier3d-compat');
  // init() prints a deprecation warning about its arguments on stderr; harmless.
  await R.init();
  return R;
}

// One engine (a world of its own) on a loaded module.
const make = (R, setting) => new RapierEngine(R, setting === 'best');

module.exports = { load, make, wasmFile: null, packageName: PACKAGE, precision: 'float32' };
