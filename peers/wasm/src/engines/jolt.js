'use strict';
// Jolt (jolt-physics, its single-threaded wasm-compat build, float32)
// builds any world the lab describes: one jolt.Step(h, 1) per fixed step
// (one collision step, no substeps).
//
// How the world maps onto Jolt:
// - each geom is one leaf shape whose user data is the geom's index; a
//   body's geoms sit in a compound (or a rotated-translated shape), shifted
//   so that the body's origin is its centre of mass, as in the world file;
//   a static geom is a static body; a plane is Jolt's plane shape;
// - capsules and cylinders lie along y in Jolt, along z in ODE: turned;
// - the mass and the full inertia tensor are given as they are
//   (MassAndInertiaProvided);
// - a contact listener gives every contact the surface of its pair of geoms
//   (ContactSettings' combined friction and restitution), and a shape filter
//   keeps apart the geoms ODE keeps apart (collide bits, joined bodies);
// - each joint is Jolt's own (point, hinge, slider, fixed), its first body
//   ODE's body2 (or the world) and its second ODE's body1, so that Jolt's
//   hinge angle and slider position (body 2 against body 1) are ODE's;
// - a force for one step is Jolt's AddForce/AddTorque (cleared after a step).
// "best": no damping (Jolt's default 0.05 linear and angular), 50 velocity
// and 10 position iterations (default 10 and 2), restitution from the
// world's own bounce velocity (default: none below 1 m/s), speed caps out of
// reach (default 500 m/s, 47 rad/s), and swept motion (LinearCast) for every
// moving body, which Jolt uses only when a body moves far in a step.
const { StepClock } = require('./clock');
const { World } = require('./world');
const { Notes, fmt } = require('./notes');
const m = require('./math');
const { commonNotes, frictionValue } = require('./translate');
const { STATIC, MOVING, joltInterface } = require('./jolt_interface');

const PACKAGE = 'jolt-physics';
const NO_SPEED_LIMIT = 1e9;
const CONVEX_RADIUS = 0.05;  // Jolt's default
const BEST_VELOCITY_STEPS = 50, BEST_POSITION_STEPS = 10;
const LARGEST_FRICTION = 1e6;
const PLANE_HALF_EXTENT = 1000;

class JoltEngine {
  constructor(J, best) {
    this.J = J;
    this.best = best;
    this.notes = new Notes();
    this.bodies = [];   // per body index: { body, id, joints } or null once removed
    this.removedSet = new Set();
    this.contacts = 0;
    this.clock = new StepClock();
  }

  // The end of a session, or a fresh engine taking over ('reset'):
  // the physics system (its bodies, shapes and
  // constraints with it) and the callbacks given back to the module, which
  // a page shares between sessions. JoltInterface owns the layer tables.
  dispose() {
    const J = this.J;
    if (!this.jolt) return;
    J.destroy(this.jolt);
    this.jolt = null;
    this.system = this.bi = null;
    for (const callback of [this.listener, this.filter]) if (callback) J.destroy(callback);
    this.listener = this.filter = null;
    this.bodies = [];
  }

  v3(a) { return new this.J.Vec3(a[0], a[1], a[2]); }
  rv3(a) { return new this.J.RVec3(a[0], a[1], a[2]); }
  quat(q) { return new this.J.Quat(q[1], q[2], q[3], q[0]); }

  build(json, removed = []) {
    const J = this.J;
    for (const r of removed) this.removedSet.add(r);
    this.world = new World(json, [...this.removedSet]);
    this.jolt = joltInterface(J);
    this.system = this.jolt.GetPhysicsSystem();
    this.bi = this.system.GetBodyInterface();
    this.installListener();
    this.installFilter();
    this.applySettings();
    this.addFrom(0, 0, 0);
  }

  add(json, firstBody, firstGeom, firstJoint) {
    this.world = new World(json, [...this.removedSet]);
    this.addFrom(firstBody, firstGeom, firstJoint);
    this.surfaceNotes();
  }

  applySettings() {
    const J = this.J, w = this.world, s = w.settings;
    this.h = s.step;
    const g = this.v3(s.gravity);
    this.system.SetGravity(g);
    J.destroy(g);
    const physics = this.system.GetPhysicsSettings();
    if (this.best) {
      physics.mNumVelocitySteps = BEST_VELOCITY_STEPS;
      physics.mNumPositionSteps = BEST_POSITION_STEPS;
    }
    // ODE's bounce velocity is Jolt's restitution threshold, one per world.
    const bouncing = w.surfacesInUse().filter((sf) => sf.bounce && sf.restitution > 0);
    if (bouncing.length) {
      const threshold = Math.min(...bouncing.map((sf) => sf.bounceVelocity));
      if (this.best) {
        physics.mMinVelocityForRestitution = threshold;
        if (bouncing.some((sf) => sf.bounceVelocity !== threshold))
          this.notes.add(`Jolt has one restitution threshold per world: every surface bounces above ${fmt(threshold)} m/s, the least of the world's bounce velocities`);
      } else if (physics.mMinVelocityForRestitution !== threshold) {
        this.notes.add(`Jolt bounces only above ${fmt(physics.mMinVelocityForRestitution)} m/s (its default restitution threshold), not above the world's bounce velocity ${fmt(threshold)} m/s (best sets it)`);
      }
    }
    const autoDisabled = w.bodies.find((b) => b.autoDisable.on);
    if (autoDisabled) {
      physics.mPointVelocitySleepThreshold = autoDisabled.autoDisable.linearThreshold;
      this.notes.add(`ODE's auto-disable became Jolt's sleeping: a body sleeps when its points move slower than ${fmt(autoDisabled.autoDisable.linearThreshold)} m/s for ${fmt(physics.mTimeBeforeSleep)} s (ODE: its linear and angular speeds for ${autoDisabled.autoDisable.steps} steps)`);
    }
    this.system.SetPhysicsSettings(physics);
    this.notes.add(`Jolt solves with ${physics.mNumVelocitySteps} velocity and ${physics.mNumPositionSteps} position iterations, not the world's ${s.iterations} QuickStep iterations`);
    commonNotes(w, this.notes, 'Jolt', { iterations: true, bounceVelocity: true, maxAngularSpeed: true });
    this.surfaceNotes();
  }

  surfaceNotes() {
    for (const sf of this.world.surfacesInUse()) frictionValue(sf.mu, LARGEST_FRICTION, this.notes, 'Jolt');
  }

  // The contact listener: each contact's friction and restitution from its
  // pair of geoms, and the count of contact points for contactCount().
  installListener() {
    const J = this.J;
    const listener = new J.ContactListenerJS();
    const surface = (body1, body2, manifold, settings) => {
      const b1 = J.wrapPointer(body1, J.Body), b2 = J.wrapPointer(body2, J.Body);
      const mf = J.wrapPointer(manifold, J.ContactManifold);
      const cs = J.wrapPointer(settings, J.ContactSettings);
      const g1 = b1.GetShape().GetSubShapeUserData(mf.mSubShapeID1);
      const g2 = b2.GetShape().GetSubShapeUserData(mf.mSubShapeID2);
      const sf = this.world.surfaceBetween(g1, g2);
      cs.mCombinedFriction = sf.mu === Infinity ? LARGEST_FRICTION : sf.mu;
      cs.mCombinedRestitution = sf.bounce ? sf.restitution : 0;
      this.contacts += mf.mRelativeContactPointsOn1.size();
    };
    listener.OnContactValidate = () => J.ValidateResult_AcceptAllContactsForThisBodyPair;
    listener.OnContactAdded = surface;
    listener.OnContactPersisted = surface;
    listener.OnContactRemoved = () => {};
    this.system.SetContactListener(listener);
    this.listener = listener;
  }

  // The shape filter: ODE's collide bits and joined bodies. Installed only
  // when the world has either (it costs a call per pair of shapes).
  installFilter() {
    const w = this.world;
    if (!w.hasCollideBits() && !w.joints.some((j) => j.body1 >= 0 && j.body2 >= 0)) return;
    const J = this.J;
    const filter = new J.SimShapeFilterJS();
    filter.ShouldCollide = (body1, shape1, sub1, body2, shape2, sub2) => {
      const g1 = J.wrapPointer(shape1, J.Shape).GetSubShapeUserData(J.wrapPointer(sub1, J.SubShapeID));
      const g2 = J.wrapPointer(shape2, J.Shape).GetSubShapeUserData(J.wrapPointer(sub2, J.SubShapeID));
      return this.world.mayTouch(g1, g2);
    };
    this.system.SetSimShapeFilter(filter);
    this.filter = filter;
  }

  // A geom's leaf shape settings, its user data the geom's index.
  leafSettings(g, index) {
    const J = this.J;
    let s;
    switch (g.shape) {
      case 'box': {
        const half = g.size.map((x) => x / 2);
        const radius = Math.min(CONVEX_RADIUS, ...half);
        this.notes.add(`Jolt rounds a box's edges and corners with its convex radius (${fmt(CONVEX_RADIUS)} m, or half the box's thinnest side where that is less)`);
        const he = this.v3(half);
        s = new J.BoxShapeSettings(he, radius);
        J.destroy(he);
        break;
      }
      case 'sphere':
        s = new J.SphereShapeSettings(g.size[0]);
        break;
      case 'capsule':
        s = new J.CapsuleShapeSettings(g.size[1] / 2, g.size[0]);
        break;
      case 'cylinder': {
        const radius = Math.min(CONVEX_RADIUS, g.size[0], g.size[1] / 2);
        this.notes.add(`Jolt rounds a cylinder's rims with its convex radius (${fmt(CONVEX_RADIUS)} m or less)`);
        s = new J.CylinderShapeSettings(g.size[1] / 2, g.size[0], radius);
        break;
      }
      default:
        throw new Error(`Jolt: no shape '${g.shape}' on a body`);
    }
    s.mUserData = index;
    return s;
  }

  // Capsules and cylinders turned from Jolt's y onto ODE's z.
  static leafRotation(g) {
    return g.shape === 'capsule' || g.shape === 'cylinder' ? m.qmul(g.orientation, m.Y_TO_Z) : g.orientation;
  }

  // A body's shape: its geoms at their offsets, the origin at the centre of mass.
  bodyShape(geoms) {
    const J = this.J, w = this.world;
    let settings;
    if (geoms.length === 1) {
      const g = w.geoms[geoms[0]];
      const leaf = this.leafSettings(g, geoms[0]);
      const rotation = JoltEngine.leafRotation(g);
      const plain = rotation.every((c, i) => c === [1, 0, 0, 0][i]) && g.position.every((c) => c === 0);
      if (plain) return leaf.Create().Get();
      const p = this.v3(g.position), q = this.quat(rotation);
      settings = new J.RotatedTranslatedShapeSettings(p, q, leaf);
    } else {
      settings = new J.StaticCompoundShapeSettings();
      for (const i of geoms) {
        const g = w.geoms[i];
        const p = this.v3(g.position), q = this.quat(JoltEngine.leafRotation(g));
        settings.AddShapeShapeSettings(p, q, this.leafSettings(g, i), i);
      }
    }
    const result = settings.Create();
    if (result.HasError()) throw new Error(`Jolt: a body's shape: ${result.GetError().c_str()}`);
    const shape = result.Get();
    const com = shape.GetCenterOfMass();
    if (com.GetX() === 0 && com.GetY() === 0 && com.GetZ() === 0) return shape;
    const offset = new J.Vec3(-com.GetX(), -com.GetY(), -com.GetZ());
    const shifted = new J.OffsetCenterOfMassShapeSettings(offset, settings).Create();
    if (shifted.HasError()) throw new Error(`Jolt: a body's shape: ${shifted.GetError().c_str()}`);
    return shifted.Get();
  }

  addFrom(firstBody, firstGeom, firstJoint) {
    const J = this.J, w = this.world;
    for (let g = firstGeom; g < w.geoms.length; ++g) {
      const geom = w.geoms[g];
      if (geom.body >= 0) continue;
      let shape, position = geom.position, rotation = JoltEngine.leafRotation(geom);
      if (geom.shape === 'plane') {
        const n = this.v3(m.unit(geom.plane.slice(0, 3)));
        shape = new J.PlaneShape(new J.Plane(n, -geom.plane[3]), null, PLANE_HALF_EXTENT);
        shape.SetUserData(g);
        position = [0, 0, 0];
        rotation = [1, 0, 0, 0];
        this.notes.add(`a plane is Jolt's plane shape, ${2 * PLANE_HALF_EXTENT} m across`);
      } else {
        shape = this.leafSettings(geom, g).Create().Get();
      }
      const p = this.rv3(position), q = this.quat(rotation);
      const s = new J.BodyCreationSettings(shape, p, q, J.EMotionType_Static, STATIC);
      const body = this.bi.CreateBody(s);
      J.destroy(s);
      this.bi.AddBody(body.GetID(), J.EActivation_DontActivate);
    }
    for (let b = firstBody; b < w.bodies.length; ++b) this.bodies[b] = w.removed.has(b) ? null : this.makeBody(b);
    if (!this.filter && (w.hasCollideBits() || w.joints.some((j) => j.body1 >= 0 && j.body2 >= 0))) this.installFilter();
    for (let j = firstJoint; j < w.joints.length; ++j) this.makeJoint(w.joints[j]);
  }

  makeBody(index) {
    const J = this.J, body = this.world.bodies[index];
    const geoms = this.world.geomsOf(index);
    if (!geoms.length) throw new Error(`Jolt: body ${index} has no geom (a body needs a shape in Jolt)`);
    const shape = this.bodyShape(geoms);
    const p = this.rv3(body.position), q = this.quat(body.orientation);
    const s = new J.BodyCreationSettings(shape, p, q, body.kinematic ? J.EMotionType_Kinematic : J.EMotionType_Dynamic, MOVING);
    s.mOverrideMassProperties = J.EOverrideMassProperties_MassAndInertiaProvided;
    s.mMassPropertiesOverride.mMass = body.mass;
    const [xx, yy, zz, xy, xz, yz] = body.inertia;
    const inertia = s.mMassPropertiesOverride.mInertia;
    for (const [col, v] of [[0, [xx, xy, xz]], [1, [xy, yy, yz]], [2, [xz, yz, zz]]]) {
      const c = this.v3(v);
      inertia.SetColumn3(col, c);
      J.destroy(c);
    }
    if (this.best) {
      s.mLinearDamping = 0;
      s.mAngularDamping = 0;
      s.mMaxLinearVelocity = NO_SPEED_LIMIT;
      s.mMaxAngularVelocity = NO_SPEED_LIMIT;
      s.mMotionQuality = J.EMotionQuality_LinearCast;
    } else {
      this.notes.add(`Jolt damps every body by default (linear ${fmt(s.mLinearDamping)}, angular ${fmt(s.mAngularDamping)}); the world has no damping (best sets it to 0)`);
      this.notes.add(`Jolt caps every body's speed at ${fmt(s.mMaxLinearVelocity)} m/s and ${fmt(s.mMaxAngularVelocity)} rad/s (its defaults; best raises them out of reach)`);
    }
    if (body.maxAngularSpeed !== Infinity) s.mMaxAngularVelocity = body.maxAngularSpeed;
    if (!body.gravity) s.mGravityFactor = 0;
    s.mAllowSleeping = body.autoDisable.on;
    const created = this.bi.CreateBody(s);
    J.destroy(s);
    const id = created.GetID();
    this.bi.AddBody(id, !body.enabled && body.autoDisable.on ? J.EActivation_DontActivate : J.EActivation_Activate);
    if (!body.enabled && !body.autoDisable.on) this.notes.add('a body exported asleep without auto-disable starts awake in Jolt');
    const v = this.v3(body.linearVelocity), w = this.v3(body.angularVelocity);
    this.bi.SetLinearVelocity(id, v);
    this.bi.SetAngularVelocity(id, w);
    J.destroy(v);
    J.destroy(w);
    return { body: created, id, joints: [] };
  }

  // "The world" in a joint: a static body with an empty shape at the origin
  // (this JS build does not export Jolt's Body::sFixedToWorld).
  joltBody(index) {
    if (index >= 0) return this.bodies[index].body;
    if (!this.anchor) {
      const J = this.J;
      const s = new J.BodyCreationSettings(new J.EmptyShape(), new J.RVec3(0, 0, 0), J.Quat.prototype.sIdentity(),
        J.EMotionType_Static, STATIC);
      this.anchor = this.bi.CreateBody(s);
      J.destroy(s);
      this.bi.AddBody(this.anchor.GetID(), J.EActivation_DontActivate);
    }
    return this.anchor;
  }

  centre(index) {
    const c = this.bodies[index].body.GetCenterOfMassPosition();
    return [c.GetX(), c.GetY(), c.GetZ()];
  }

  // A joint's stops in Jolt, which wants the lower in [-limit, 0] and the upper in [0, limit].
  stops(joint, limit, unit) {
    let lo = Math.max(joint.lowStop, -limit), hi = Math.min(joint.highStop, limit);
    if (lo > 0 || hi < 0) {
      this.notes.add(`Jolt's ${joint.type} limits must hold the built position: stops ${fmt(joint.lowStop)}..${fmt(joint.highStop)} ${unit} became ${fmt(Math.min(lo, 0))}..${fmt(Math.max(hi, 0))}`);
      lo = Math.min(lo, 0);
      hi = Math.max(hi, 0);
    }
    return [lo, hi];
  }

  makeJoint(joint) {
    const J = this.J;
    if ((joint.body1 >= 0 && !this.bodies[joint.body1]) || (joint.body2 >= 0 && !this.bodies[joint.body2])) return;
    const first = joint.body2, second = joint.body1;
    const axis = m.unit(joint.axis), normal = m.perpendicular(axis);
    let s;
    switch (joint.type) {
      case 'ball':
        s = new J.PointConstraintSettings();
        s.mPoint1 = s.mPoint2 = this.rv3(joint.anchor);
        break;
      case 'hinge': {
        s = new J.HingeConstraintSettings();
        s.mPoint1 = s.mPoint2 = this.rv3(joint.anchor);
        s.mHingeAxis1 = s.mHingeAxis2 = this.v3(axis);
        s.mNormalAxis1 = s.mNormalAxis2 = this.v3(normal);
        if (joint.lowStop !== -Infinity || joint.highStop !== Infinity)
          [s.mLimitsMin, s.mLimitsMax] = this.stops(joint, Math.PI, 'rad');
        break;
      }
      case 'slider': {
        s = new J.SliderConstraintSettings();
        const at = second >= 0 ? this.centre(second) : this.centre(first);
        s.mPoint1 = s.mPoint2 = this.rv3(at);
        s.mSliderAxis1 = s.mSliderAxis2 = this.v3(axis);
        s.mNormalAxis1 = s.mNormalAxis2 = this.v3(normal);
        if (joint.lowStop !== -Infinity || joint.highStop !== Infinity)
          [s.mLimitsMin, s.mLimitsMax] = this.stops(joint, 1e9, 'm');
        break;
      }
      case 'fixed':
        s = new J.FixedConstraintSettings();
        s.mAutoDetectPoint = true;
        break;
      default:
        throw new Error(`Jolt: no joint type '${joint.type}'`);
    }
    const constraint = s.Create(this.joltBody(first), this.joltBody(second));
    this.system.AddConstraint(constraint);
    for (const b of [joint.body1, joint.body2]) if (b >= 0) this.bodies[b].joints.push(constraint);
  }

  remove(index) {
    const body = this.bodies[index];
    if (!body) return;
    for (const c of body.joints) {
      this.system.RemoveConstraint(c);
      for (const other of this.bodies) if (other && other !== body) other.joints = other.joints.filter((k) => k !== c);
    }
    this.bi.RemoveBody(body.id);
    this.bi.DestroyBody(body.id);
    this.bodies[index] = null;
    this.removedSet.add(index);
  }

  setState(index, s) {
    const J = this.J, body = this.bodies[index];
    if (!body) return;
    const asleep = s.length > 13 && !s[13];
    const p = this.rv3(s.slice(0, 3)), q = this.quat(s.slice(3, 7)), v = this.v3(s.slice(7, 10)), w = this.v3(s.slice(10, 13));
    this.bi.SetPositionAndRotation(body.id, p, q, asleep ? J.EActivation_DontActivate : J.EActivation_Activate);
    this.bi.SetLinearVelocity(body.id, v);
    this.bi.SetAngularVelocity(body.id, w);
    if (asleep) this.bi.DeactivateBody(body.id);
    else this.bi.ActivateBody(body.id);
    for (const x of [p, q, v, w]) J.destroy(x);
  }

  applyForce(index, force, torque) {
    const J = this.J, body = this.bodies[index];
    if (!body) return;
    const f = this.v3(force), t = this.v3(torque);
    this.bi.AddForce(body.id, f, J.EActivation_Activate);
    this.bi.AddTorque(body.id, t, J.EActivation_Activate);
    J.destroy(f);
    J.destroy(t);
  }

  changeSettings(json) {
    this.world = new World(json, [...this.removedSet]);
    this.applySettings();
  }

  step() {
    this.contacts = 0;
    this.clock.time(() => this.jolt.Step(this.h, 1));
  }

  state(index) {
    const entry = this.bodies[index];
    if (!entry) return null;
    const b = entry.body;
    const p = b.GetCenterOfMassPosition(), q = b.GetRotation(), v = b.GetLinearVelocity(), w = b.GetAngularVelocity();
    return [p.GetX(), p.GetY(), p.GetZ(), q.GetW(), q.GetX(), q.GetY(), q.GetZ(),
      v.GetX(), v.GetY(), v.GetZ(), w.GetX(), w.GetY(), w.GetZ(), b.IsActive() ? 1 : 0];
  }

  contactCount() {
    return this.contacts;
  }

  wallSeconds() {
    return this.clock.wallSeconds();
  }

  cpuSeconds() {
    return this.clock.cpuSeconds();
  }
}

// The WebAssembly module (inlined in the package's wasm-compat build),
// loaded once per process or page.
async function load() {
  const { default: initJolt } = await import('jolt-physics/wasm-compat');
  return initJolt();
}

// One engine on a loaded module.
const make = (J, setting) => new JoltEngine(J, setting === 'best');

module.exports = { load, make, wasmFile: null, packageName: PACKAGE, precision: 'float32' };
