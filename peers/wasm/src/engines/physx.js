'use strict';
// PhysX 5 (physx-js-webidl, NVIDIA PhysX 5.6.1 in WebAssembly, float32)
// builds any world the lab describes of boxes, spheres, capsules and planes:
// one scene.simulate(h) and fetchResults per fixed step, on the caller's
// thread (a CPU dispatcher of no worker threads).
//
// How the world maps onto PhysX:
// - each body is a PxRigidDynamic whose actor frame is its centre of mass
//   (the world file's origin); each geom is one exclusive shape on it at its
//   offset; a static geom is a PxRigidStatic of its own; a plane is PhysX's
//   half-space (PxPlaneGeometry, its normal the shape's x axis);
// - capsules lie along x in PhysX, along z in ODE: turned; PhysX 5 has no
//   cylinder primitive, so a world with one is refused, naming it;
// - the mass and the full inertia tensor go in as principal moments and
//   their frame (setMassSpaceInertiaTensor, setCMassLocalPose);
// - each surface per pair becomes per-shape materials and one combine rule
//   (materials.js): the JS binding has no contact-modify callback. A
//   material's static and dynamic friction are both ODE's mu;
// - a pass-through filter shader keeps apart the geoms ODE's collide bits
//   keep apart; joined bodies do not touch (PhysX joints leave collision
//   off between their two actors), as in ODE's programs;
// - each joint is PhysX's own (spherical, revolute, prismatic, fixed), its
//   actor0 ODE's body2 (or the world) and its actor1 ODE's body1, so that
//   the revolute angle and prismatic position (actor1 against actor0) are
//   ODE's; the joint frame's x axis is the hinge or slider axis;
// - a force for one step is PxRigidBody.addForce/addTorque (PhysX clears
//   them after the step);
// - every touching pair reports its contact points (touch found and
//   persists) to a simulation event callback, which counts them.
// "best": the TGS solver (PxSolverType::eTGS: better convergence for long
// chains, large mass ratios and jointed systems, PhysX's API reference says,
// at some cost, and it "can introduce more energy to correct joint and
// contact errors") with 32 position and 4 velocity iterations per body
// (default PGS with 4 and 1), no damping (default angular 0.05), the speed
// caps out of reach, restitution from the world's bounce velocity (PhysX's
// default threshold is 2 m/s), and swept CCD on every moving body.
const { StepClock } = require('./clock');
const { World } = require('./world');
const { Notes, fmt } = require('./notes');
const m = require('./math');
const { planMaterial, relevantPairs } = require('./materials');
const { commonNotes, frictionValue, planNotes } = require('./translate');

const PACKAGE = 'physx-js-webidl';
const BEST_POSITION_ITERATIONS = 32, BEST_VELOCITY_ITERATIONS = 4;
const NO_SPEED_LIMIT = 1e9;
const LARGEST_FRICTION = 1e6;
const OPEN_LIMIT = 1e6;             // a slider stop on one side only: the other far beyond reach
const ANGLE_LIMIT = 2 * Math.PI - 1e-3;  // PhysX wants revolute limits inside (-2 pi, 2 pi)
const RULE_NAMES = { min: 'minimum', max: 'maximum', average: 'average', multiply: 'product' };
// Capsules lie along x in PhysX: this turns x onto z (-90 degrees about y).
const X_TO_Z = [Math.SQRT1_2, 0, -Math.SQRT1_2, 0];

// The one foundation and physics object a module may hold (PhysX allows
// one foundation per process), made on first use.
function sdkOf(P) {
  if (!P.odelabSdk) {
    const version = P.PHYSICS_VERSION;
    const foundation = P.CreateFoundation(version, new P.PxDefaultAllocator(), new P.PxDefaultErrorCallback());
    const tolerances = new P.PxTolerancesScale();
    const physics = P.CreatePhysics(version, foundation, tolerances);
    P.InitExtensions(physics);
    P.odelabSdk = { foundation, tolerances, physics, dispatcher: P.DefaultCpuDispatcherCreate(0) };
  }
  return P.odelabSdk;
}

class PhysxEngine {
  constructor(P, best) {
    this.P = P;
    this.best = best;
    this.notes = new Notes();
    this.bodies = [];     // per body index: { actor, kinematic } or null once removed
    this.shapes = [];     // per geom index: the shape, or null
    this.statics = [];    // the static actors of static geoms
    this.removedSet = new Set();
    this.clock = new StepClock();
  }

  v3(a) { return new this.P.PxVec3(a[0], a[1], a[2]); }
  quat(q) { return new this.P.PxQuat(q[1], q[2], q[3], q[0]); }
  transform(p, q) { return new this.P.PxTransform(this.v3(p), this.quat(q)); }
  flag(enumName, name) { return this.P[enumName][name]; }

  build(json, removed = []) {
    const P = this.P;
    for (const r of removed) this.removedSet.add(r);
    this.world = new World(json, [...this.removedSet]);
    for (const g of this.world.geoms)
      if (g.shape === 'cylinder') throw new Error('PhysX 5 has no cylinder shape (only as a convex mesh, which this adapter does not make): a world with a cylinder cannot be built');
    const sdk = sdkOf(P);
    this.physics = sdk.physics;
    // A world built again (the scene reset): the old scene goes, with its
    // actors and joints, from the module's memory, which every session shares.
    if (this.scene) this.releaseScene();
    const desc = new P.PxSceneDesc(sdk.tolerances);
    desc.gravity = this.v3(this.world.settings.gravity);
    desc.cpuDispatcher = sdk.dispatcher;
    desc.solverType = this.best ? P.PxSolverTypeEnum.eTGS : P.PxSolverTypeEnum.ePGS;
    if (this.best) desc.flags.raise(P.PxSceneFlagEnum.eENABLE_CCD);
    this.defaultBounceThreshold = desc.bounceThresholdVelocity;
    this.shader = this.filterShader();
    P.setupPassThroughFilterShader(desc, this.shader);
    this.listener = this.contactListener();
    desc.simulationEventCallback = this.listener;
    this.scene = this.physics.createScene(desc);
    P.destroy(desc);
    this.applySettings();
    this.addFrom(0, 0, 0);
  }

  add(json, firstBody, firstGeom, firstJoint) {
    this.world = new World(json, [...this.removedSet]);
    this.addFrom(firstBody, firstGeom, firstJoint);
  }

  // ODE's collide bits: word0 of a shape's filter data its category, word1
  // its collide bits; a pair touches when either's category meets the
  // other's collide bits. Best asks for swept contacts (CCD) on every pair.
  filterShader() {
    const P = this.P;
    const shader = new P.PassThroughFilterShaderImpl();
    // The contact points of every touching pair are reported (contactCount()).
    let pairFlags = P.PxPairFlagEnum.eCONTACT_DEFAULT | P.PxPairFlagEnum.eNOTIFY_TOUCH_FOUND
      | P.PxPairFlagEnum.eNOTIFY_TOUCH_PERSISTS | P.PxPairFlagEnum.eNOTIFY_CONTACT_POINTS;
    if (this.best) pairFlags |= P.PxPairFlagEnum.eDETECT_CCD_CONTACT;
    const suppress = P.PxFilterFlagEnum.eSUPPRESS;
    shader.filterShader = (a0, category0, collide0, w02, w03, a1, category1, collide1) => {
      if (((category0 & collide1) >>> 0) === 0 && ((category1 & collide0) >>> 0) === 0) return suppress;
      shader.outputPairFlags = pairFlags;
      return 0;
    };
    return shader;
  }

  // The simulation's contact reports: the count of contact points of the
  // pairs that touched in the last step.
  contactListener() {
    const P = this.P;
    const listener = new P.PxSimulationEventCallbackImpl();
    listener.onConstraintBreak = listener.onWake = listener.onSleep = listener.onTrigger = () => {};
    listener.onContact = (header, pairs, count) => {
      for (let i = 0; i < count; ++i) this.contacts += P.getContactPairAt(P.wrapPointer(pairs, P.PxContactPair), i).contactCount;
    };
    return listener;
  }

  applySettings() {
    const P = this.P, w = this.world, s = w.settings;
    this.h = s.step;
    this.scene.setGravity(this.v3(s.gravity));
    const positions = this.best ? BEST_POSITION_ITERATIONS : 4, velocities = this.best ? BEST_VELOCITY_ITERATIONS : 1;
    this.iterations = [positions, velocities];
    this.notes.add(`PhysX solves with ${this.best ? 'TGS' : 'PGS'}, ${positions} position and ${velocities} velocity iterations per body, not the world's ${s.iterations} QuickStep iterations`);
    // ODE's bounce velocity is PhysX's bounce threshold, one per scene.
    const bouncing = w.surfacesInUse().filter((sf) => sf.bounce && sf.restitution > 0);
    if (bouncing.length) {
      const threshold = Math.min(...bouncing.map((sf) => sf.bounceVelocity));
      if (this.best) {
        // PhysX wants a threshold above zero: the least float32 step stands for 0.
        this.scene.setBounceThresholdVelocity(Math.max(threshold, 1e-6));
        if (bouncing.some((sf) => sf.bounceVelocity !== threshold))
          this.notes.add(`PhysX has one bounce threshold per scene: every surface bounces above ${fmt(threshold)} m/s, the least of the world's bounce velocities`);
      } else if (Math.abs(this.defaultBounceThreshold - threshold) > 1e-9) {
        this.notes.add(`PhysX bounces only above ${fmt(this.defaultBounceThreshold)} m/s (its default bounce threshold), not above the world's bounce velocity ${fmt(threshold)} m/s (best sets it)`);
      }
    }
    commonNotes(w, this.notes, 'PhysX', { iterations: true, bounceVelocity: true, maxAngularSpeed: true });
  }

  // A geom's PhysX geometry.
  geometry(g) {
    const P = this.P;
    switch (g.shape) {
      case 'box':
        return new P.PxBoxGeometry(g.size[0] / 2, g.size[1] / 2, g.size[2] / 2);
      case 'sphere':
        return new P.PxSphereGeometry(g.size[0]);
      case 'capsule':
        return new P.PxCapsuleGeometry(g.size[0], g.size[1] / 2);
      case 'plane':
        return new P.PxPlaneGeometry();
      default:
        throw new Error(`PhysX: no shape '${g.shape}'`);
    }
  }

  // A geom's pose on its body (a static geom's in the world).
  static pose(g) {
    if (g.shape === 'plane') {
      const n = m.unit(g.plane.slice(0, 3));
      return [m.scale(n, g.plane[3]), m.frameFrom(n)];
    }
    return [g.position, g.shape === 'capsule' ? m.qmul(g.orientation, X_TO_Z) : g.orientation];
  }

  makeShape(g, index) {
    const P = this.P;
    const geom = this.world.geoms[g];
    const material = this.physics.createMaterial(0.5, 0.5, 0);  // set by applyMaterials
    const flags = new P.PxShapeFlags(P.PxShapeFlagEnum.eSIMULATION_SHAPE | P.PxShapeFlagEnum.eSCENE_QUERY_SHAPE);
    const shape = this.physics.createShape(this.geometry(geom), material, true, flags);
    const [p, q] = PhysxEngine.pose(geom);
    shape.setLocalPose(this.transform(p, q));
    shape.setSimulationFilterData(new P.PxFilterData(geom.category | 0, geom.collide | 0, index, 0));
    shape.odelabMaterial = material;
    this.notes.add(`PhysX makes a contact once two shapes come within the sum of their contact offsets (${fmt(shape.getContactOffset())} m each, its default), before they touch, and rests them at the sum of their rest offsets (${fmt(shape.getRestOffset())} m each)`);
    if (geom.shape === 'plane') this.notes.add("a plane is PhysX's half-space (PxPlaneGeometry)");
    return shape;
  }

  addFrom(firstBody, firstGeom, firstJoint) {
    const w = this.world;
    for (let b = firstBody; b < w.bodies.length; ++b) this.bodies[b] = w.removed.has(b) ? null : this.makeBody(b);
    for (let g = firstGeom; g < w.geoms.length; ++g) {
      const geom = w.geoms[g];
      const owner = geom.body >= 0 ? this.bodies[geom.body] : null;
      if (geom.body >= 0 && !owner) { this.shapes[g] = null; continue; }
      const shape = this.makeShape(g, g);
      this.shapes[g] = shape;
      if (owner) {
        owner.actor.attachShape(shape);
      } else {
        const actor = this.physics.createRigidStatic(this.transform([0, 0, 0], [1, 0, 0, 0]));
        actor.attachShape(shape);
        this.scene.addActor(actor);
        this.statics.push(actor);
      }
    }
    for (let b = firstBody; b < w.bodies.length; ++b) {
      const entry = this.bodies[b];
      if (!entry || entry.added) continue;
      if (!w.geomsOf(b).length) throw new Error(`PhysX: body ${b} has no geom`);
      this.scene.addActor(entry.actor);
      entry.added = true;
      this.startMoving(b);
    }
    this.applyMaterials();
    for (let j = firstJoint; j < w.joints.length; ++j) this.makeJoint(w.joints[j]);
  }

  makeBody(index) {
    const P = this.P, body = this.world.bodies[index];
    const actor = this.physics.createRigidDynamic(this.transform(body.position, body.orientation));
    const { moments, rotation } = m.principalInertia(body.inertia);
    actor.setMass(body.mass);
    actor.setMassSpaceInertiaTensor(this.v3(moments));
    actor.setCMassLocalPose(this.transform([0, 0, 0], rotation));
    actor.setSolverIterationCounts(this.iterations[0], this.iterations[1]);
    if (this.best) {
      actor.setLinearDamping(0);
      actor.setAngularDamping(0);
      actor.setMaxLinearVelocity(NO_SPEED_LIMIT);
      actor.setMaxAngularVelocity(NO_SPEED_LIMIT);
      actor.setMaxDepenetrationVelocity(NO_SPEED_LIMIT);
      actor.setRigidBodyFlag(P.PxRigidBodyFlagEnum.eENABLE_CCD, true);
    } else {
      this.notes.add(`PhysX damps every body by default (linear ${fmt(actor.getLinearDamping())}, angular ${fmt(actor.getAngularDamping())}); the world has no damping (best sets it to 0)`);
      // (Its default linear cap, 1e16 m/s, and its cap on the push out of
      // penetration, 1e32 m/s, are none; the angular cap is.)
      const caps = [[actor.getMaxLinearVelocity(), 'm/s'], [actor.getMaxAngularVelocity(), 'rad/s']]
        .filter(([cap]) => cap < NO_SPEED_LIMIT).map(([cap, unit]) => `${fmt(cap)} ${unit}`);
      if (caps.length) this.notes.add(`PhysX caps every body's speed at ${caps.join(' and ')} (its default; best raises it out of reach)`);
    }
    if (body.maxAngularSpeed !== Infinity) actor.setMaxAngularVelocity(body.maxAngularSpeed);
    if (!body.gravity) actor.setActorFlag(P.PxActorFlagEnum.eDISABLE_GRAVITY, true);
    if (body.kinematic) actor.setRigidBodyFlag(P.PxRigidBodyFlagEnum.eKINEMATIC, true);
    // ODE's auto-disable off: never sleep (a threshold of 0 kinetic energy
    // per unit mass is never undercut). On: PhysX's sleeping, its threshold
    // the kinetic energy per unit mass of ODE's linear threshold.
    const ad = body.autoDisable;
    if (ad.on) {
      actor.setSleepThreshold(0.5 * ad.linearThreshold * ad.linearThreshold);
      this.notes.add(`ODE's auto-disable became PhysX's sleeping: a body sleeps when its kinetic energy per unit mass stays below ${fmt(0.5 * ad.linearThreshold * ad.linearThreshold)} (half the square of ${fmt(ad.linearThreshold)} m/s) for PhysX's wake counter (${fmt(actor.getWakeCounter())} s), not ODE's ${ad.steps} steps`);
    } else {
      actor.setSleepThreshold(0);
    }
    return { actor, kinematic: body.kinematic, added: false };
  }

  // A new body's velocities (set once it is in the scene) and its sleep.
  startMoving(index) {
    const body = this.world.bodies[index], actor = this.bodies[index].actor;
    if (body.kinematic) return;
    actor.setLinearVelocity(this.v3(body.linearVelocity), true);
    actor.setAngularVelocity(this.v3(body.angularVelocity), true);
    if (!body.enabled && body.autoDisable.on) actor.putToSleep();
    if (!body.enabled && !body.autoDisable.on) this.notes.add('a body exported asleep without auto-disable starts awake in PhysX');
  }

  applyMaterials() {
    const P = this.P, w = this.world;
    const built = [];
    this.shapes.forEach((s, g) => { if (s) built.push(g); });
    const cache = relevantPairs(w, built);
    const rules = ['average', 'min', 'max', 'multiply'];
    const friction = planMaterial(w, built, (s) => frictionValue(s.mu, LARGEST_FRICTION, this.notes, 'PhysX'), rules, cache);
    const restitution = planMaterial(w, built, (s) => (s.bounce ? s.restitution : 0), rules, cache);
    const name = (r) => RULE_NAMES[r];
    planNotes(friction, 'friction', 'PhysX', this.notes, name);
    planNotes(restitution, 'restitution', 'PhysX', this.notes, name);
    const mode = { average: P.PxCombineModeEnum.eAVERAGE, min: P.PxCombineModeEnum.eMIN,
      max: P.PxCombineModeEnum.eMAX, multiply: P.PxCombineModeEnum.eMULTIPLY };
    for (const g of built) {
      const material = this.shapes[g].odelabMaterial;
      material.setStaticFriction(friction.value(g));
      material.setDynamicFriction(friction.value(g));
      material.setFrictionCombineMode(mode[friction.rule]);
      material.setRestitution(restitution.value(g));
      material.setRestitutionCombineMode(mode[restitution.rule]);
    }
  }

  // A body's actor, or null for the world.
  actorOf(index) {
    return index < 0 ? null : this.bodies[index].actor;
  }

  // The pose [p, q] of a body, or the identity for the world.
  poseOf(index) {
    if (index < 0) return [[0, 0, 0], [1, 0, 0, 0]];
    const t = this.bodies[index].actor.getGlobalPose();
    return [[t.p.x, t.p.y, t.p.z], [t.q.w, t.q.x, t.q.y, t.q.z]];
  }

  // A world frame (point, rotation) in a body's frame.
  localFrame(index, point, rotation) {
    const [p, q] = this.poseOf(index);
    const inv = m.qconj(q);
    return this.transform(m.rotate(inv, m.sub(point, p)), m.qnormalize(m.qmul(inv, rotation)));
  }

  // A joint's stops in PhysX: both given (PhysX has no open side), the open
  // one far beyond reach.
  stops(joint, limit) {
    return [Math.max(joint.lowStop, -limit), Math.min(joint.highStop, limit)];
  }

  makeJoint(joint) {
    const P = this.P;
    if ((joint.body1 >= 0 && !this.bodies[joint.body1]) || (joint.body2 >= 0 && !this.bodies[joint.body2])) return;
    const first = joint.body2, second = joint.body1;
    const axis = m.unit(joint.axis);
    const centre = (i) => this.poseOf(i)[0];
    const at = joint.type === 'ball' || joint.type === 'hinge' ? joint.anchor : centre(second >= 0 ? second : first);
    const frame = joint.type === 'fixed' ? [1, 0, 0, 0] : m.frameFrom(axis);
    const f0 = this.localFrame(first, at, frame), f1 = this.localFrame(second, at, frame);
    const a0 = this.actorOf(first), a1 = this.actorOf(second);
    const limited = joint.lowStop !== -Infinity || joint.highStop !== Infinity;
    let created;
    switch (joint.type) {
      case 'ball':
        created = P.SphericalJointCreate(this.physics, a0, f0, a1, f1);
        break;
      case 'hinge':
        created = P.RevoluteJointCreate(this.physics, a0, f0, a1, f1);
        if (limited) {
          const [lo, hi] = this.stops(joint, ANGLE_LIMIT);
          if (lo !== joint.lowStop || hi !== joint.highStop)
            this.notes.add(`PhysX's revolute limits lie inside (-2 pi, 2 pi): stops ${fmt(joint.lowStop)}..${fmt(joint.highStop)} rad became ${fmt(lo)}..${fmt(hi)}`);
          created.setLimit(new P.PxJointAngularLimitPair(lo, hi));
          created.setRevoluteJointFlag(P.PxRevoluteJointFlagEnum.eLIMIT_ENABLED, true);
        }
        break;
      case 'slider':
        created = P.PrismaticJointCreate(this.physics, a0, f0, a1, f1);
        if (limited) {
          const [lo, hi] = this.stops(joint, OPEN_LIMIT);
          created.setLimit(new P.PxJointLinearLimitPair(lo, hi, new P.PxSpring(0, 0)));
          created.setPrismaticJointFlag(P.PxPrismaticJointFlagEnum.eLIMIT_ENABLED, true);
        }
        break;
      case 'fixed':
        created = P.FixedJointCreate(this.physics, a0, f0, a1, f1);
        break;
      default:
        throw new Error(`PhysX: no joint type '${joint.type}'`);
    }
    for (const b of [joint.body1, joint.body2]) if (b >= 0) (this.bodies[b].joints = this.bodies[b].joints || []).push(created);
  }

  // The session ends, or R and a rewind make a fresh engine: the scene goes
  // from the module, which every session in the process shares.
  dispose() {
    if (this.scene) this.releaseScene();
    this.scene = null;
  }

  releaseScene() {
    const joints = new Set();  // a joint is in both its bodies' lists
    for (const entry of this.bodies) for (const joint of (entry && entry.joints) || []) joints.add(joint);
    for (const joint of joints) joint.release();
    for (const entry of this.bodies) if (entry) entry.actor.release();
    for (const actor of this.statics) actor.release();
    this.scene.release();
    this.bodies = [];
    this.shapes = [];
    this.statics = [];
  }

  remove(index) {
    const entry = this.bodies[index];
    if (!entry) return;
    for (const joint of entry.joints || []) {
      joint.release();
      for (const other of this.bodies) if (other && other !== entry && other.joints) other.joints = other.joints.filter((k) => k !== joint);
    }
    this.scene.removeActor(entry.actor);
    entry.actor.release();  // its shapes go with it
    this.world.geoms.forEach((g, i) => { if (g.body === index) this.shapes[i] = null; });
    this.bodies[index] = null;
    this.removedSet.add(index);
  }

  setState(index, s) {
    const entry = this.bodies[index];
    if (!entry) return;
    const actor = entry.actor;
    actor.setGlobalPose(this.transform(s.slice(0, 3), s.slice(3, 7)), true);
    if (entry.kinematic) { entry.velocity = [s.slice(7, 10), s.slice(10, 13)]; return; }
    actor.setLinearVelocity(this.v3(s.slice(7, 10)), true);
    actor.setAngularVelocity(this.v3(s.slice(10, 13)), true);
    if (s.length > 13 && !s[13]) actor.putToSleep();
  }

  applyForce(index, force, torque) {
    const P = this.P, entry = this.bodies[index];
    if (!entry || entry.kinematic) return;
    entry.actor.addForce(this.v3(force), P.PxForceModeEnum.eFORCE, true);
    entry.actor.addTorque(this.v3(torque), P.PxForceModeEnum.eFORCE, true);
  }

  changeSettings(json) {
    this.world = new World(json, [...this.removedSet]);
    this.applySettings();
    this.applyMaterials();
  }

  // A kinematic body moves at its own velocity: its target one step on.
  moveKinematics() {
    this.bodies.forEach((entry, i) => {
      if (!entry || !entry.kinematic) return;
      const body = this.world.bodies[i];
      const [v, w] = entry.velocity || [body.linearVelocity, body.angularVelocity];
      const [p, q] = this.poseOf(i);
      const angle = m.norm(w) * this.h;
      const turn = angle > 0 ? [Math.cos(angle / 2), ...m.scale(m.unit(w), Math.sin(angle / 2))] : [1, 0, 0, 0];
      entry.actor.setKinematicTarget(this.transform(m.add(p, m.scale(v, this.h)), m.qnormalize(m.qmul(turn, q))));
      entry.velocity = [v, w];
    });
  }

  step() {
    this.moveKinematics();
    this.contacts = 0;
    this.clock.time(() => {
      this.scene.simulate(this.h);
      this.scene.fetchResults(true);
    });
  }

  state(index) {
    const entry = this.bodies[index];
    if (!entry) return null;
    const a = entry.actor;
    const t = a.getGlobalPose();
    if (entry.kinematic) {
      const [v, w] = entry.velocity || [this.world.bodies[index].linearVelocity, this.world.bodies[index].angularVelocity];
      return [t.p.x, t.p.y, t.p.z, t.q.w, t.q.x, t.q.y, t.q.z, ...v, ...w, 1];
    }
    const v = a.getLinearVelocity(), w = a.getAngularVelocity();
    return [t.p.x, t.p.y, t.p.z, t.q.w, t.q.x, t.q.y, t.q.z, v.x, v.y, v.z, w.x, w.y, w.z, a.isSleeping() ? 0 : 1];
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

// The WebAssembly module, loaded once per process or page. The package is
// built for the web only (its loader throws where it sees Node.js): in
// Node.js it is started with `process` hidden and `window` shown for the
// moment its loader looks, and given its .wasm file's bytes.
async function load({ wasmBinary } = {}) {
  const { default: init } = await import('physx-js-webidl');
  const inNode = typeof process !== 'undefined' && process.versions != null && process.versions.node != null;
  if (!inNode) return init(wasmBinary ? { wasmBinary } : {});
  const processProperty = Object.getOwnPropertyDescriptor(globalThis, 'process');
  const hadWindow = 'window' in globalThis;
  let started;
  Object.defineProperty(globalThis, 'process', { value: undefined, configurable: true, writable: true });
  if (!hadWindow) globalThis.window = globalThis;
  try {
    started = init({ wasmBinary: wasmBinary || require('fs').readFileSync(require.resolve('physx-js-webidl/physx-js-webidl.wasm')) });
  } finally {
    Object.defineProperty(globalThis, 'process', processProperty);
    if (!hadWindow) delete globalThis.window;
  }
  return started;
}

// One engine (a scene of its own) on a loaded module.
const make = (P, setting) => new PhysxEngine(P, setting === 'best');

module.exports = { load, make, wasmFile: 'physx-js-webidl/physx-js-webidl.wasm', packageName: PACKAGE, precision: 'float32' };
