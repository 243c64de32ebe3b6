'use strict';
// Jolt through its WebAssembly build (jolt-physics, the single-threaded
// wasm-compat build, float32), one jolt.Step(h, 1) per fixed step.
//
// In both settings: the speed caps (500 m/s linear, 47 rad/s angular by
// default) are raised out of reach, sleeping is off, and a box's convex
// radius is Jolt's 0.05 m only where it fits: Jolt refuses a radius above
// the smallest half extent, and test10's wall is 0.025 m thick on each side,
// so there it is that half-thickness. Restitution 1.0 on both bodies (Jolt
// combines by maximum: 1.0).
// "best" removes the damping Jolt applies by default (0.05 linear and
// angular), gives the solver 50 velocity and 10 position iterations (default
// 10 and 2), applies restitution at any impact speed (default: none below
// 1 m/s) and, on test10, sweeps the cube (motion quality LinearCast, Jolt's
// continuous collision; also --ccd).
const { scene, SURFACE_GRAVITY } = require('./constants');
const { plateStack, dominoStarts, tiltDegrees, pendulumMass, kineticEnergy, stackReadout, uprightReadout, launchedCube, throwState, hangingPairReadout } = require('./rigs');
const { ballLayout } = require('./rebound');

const NO_SPEED_LIMIT = 1e9;
const DEFAULT_CONVEX_RADIUS = 0.05;
const BEST_VELOCITY_STEPS = 50, BEST_POSITION_STEPS = 10;
const STATIC = 0, MOVING = 1;  // object layers

async function load() {
  const { default: initJolt } = await import('jolt-physics/wasm-compat');
  return initJolt();
}

class World {
  constructor(Jolt, gravity, options) {
    this.Jolt = Jolt;
    this.h = options.step;
    this.options = options;
    this.best = options.setting === 'best';
    const settings = new Jolt.JoltSettings();
    const pairs = new Jolt.ObjectLayerPairFilterTable(2);
    pairs.EnableCollision(STATIC, MOVING);
    pairs.EnableCollision(MOVING, MOVING);
    const layers = new Jolt.BroadPhaseLayerInterfaceTable(2, 2);
    layers.MapObjectToBroadPhaseLayer(STATIC, new Jolt.BroadPhaseLayer(0));
    layers.MapObjectToBroadPhaseLayer(MOVING, new Jolt.BroadPhaseLayer(1));
    settings.mObjectLayerPairFilter = pairs;
    settings.mBroadPhaseLayerInterface = layers;
    settings.mObjectVsBroadPhaseLayerFilter = new Jolt.ObjectVsBroadPhaseLayerFilterTable(layers, 2, pairs, 2);
    this.jolt = new Jolt.JoltInterface(settings);
    Jolt.destroy(settings);
    this.system = this.jolt.GetPhysicsSystem();
    this.bodies = this.system.GetBodyInterface();
    this.system.SetGravity(new Jolt.Vec3(0, -gravity, 0));
    if (this.best) {
      const physics = this.system.GetPhysicsSettings();
      physics.mNumVelocitySteps = BEST_VELOCITY_STEPS;
      physics.mNumPositionSteps = BEST_POSITION_STEPS;
      physics.mMinVelocityForRestitution = 0;
      this.system.SetPhysicsSettings(physics);
    }
  }
  box(size) {
    const radius = Math.min(DEFAULT_CONVEX_RADIUS, ...size.map((s) => s / 2));
    return new this.Jolt.BoxShape(new this.Jolt.Vec3(size[0] / 2, size[1] / 2, size[2] / 2), radius);
  }
  sphere(radius) {
    return new this.Jolt.SphereShape(radius);
  }
  plane() {  // the ground y = 0 (Jolt has a plane shape)
    return new this.Jolt.PlaneShape(new this.Jolt.Plane(new this.Jolt.Vec3(0, 1, 0), 0));
  }
  // mass 0: static. inertia: principal moments about the centre, else Jolt's from the shape.
  body(shape, mass, position, { inertia, restitution, sweep, friction, group, rotation, sleeps } = {}) {
    const J = this.Jolt;
    const s = new J.BodyCreationSettings(shape, new J.RVec3(...position),
      rotation ? new J.Quat(...rotation) : J.Quat.prototype.sIdentity(),
      mass > 0 ? J.EMotionType_Dynamic : J.EMotionType_Static, mass > 0 ? MOVING : STATIC);
    s.mAllowSleeping = Boolean(sleeps);
    s.mMaxLinearVelocity = NO_SPEED_LIMIT;
    s.mMaxAngularVelocity = NO_SPEED_LIMIT;
    if (restitution !== undefined) s.mRestitution = restitution;
    if (friction !== undefined) s.mFriction = friction;
    if (group) s.mCollisionGroup = group;
    if (this.best) {
      s.mLinearDamping = 0;
      s.mAngularDamping = 0;
    }
    if (sweep) s.mMotionQuality = J.EMotionQuality_LinearCast;
    if (mass > 0) {
      s.mOverrideMassProperties = inertia ? J.EOverrideMassProperties_MassAndInertiaProvided
        : J.EOverrideMassProperties_CalculateInertia;
      s.mMassPropertiesOverride.mMass = mass;
      if (inertia) {
        const m = J.Mat44.prototype.sScaleVec3(new J.Vec3(...inertia));
        s.mMassPropertiesOverride.mInertia = m;
      }
    }
    const body = this.bodies.CreateBody(s);
    J.destroy(s);
    this.bodies.AddBody(body.GetID(), J.EActivation_Activate);
    return body;
  }
  step() {
    this.jolt.Step(this.h, 1);
  }
  static vec(v) {
    return [v.GetX(), v.GetY(), v.GetZ()];
  }
  position(body) {
    return World.vec(body.GetCenterOfMassPosition());
  }
  rotation(body) {
    const q = body.GetRotation();
    return [q.GetX(), q.GetY(), q.GetZ(), q.GetW()];
  }
  velocity(body) {
    return World.vec(body.GetLinearVelocity());
  }
  spin(body) {
    return World.vec(body.GetAngularVelocity());
  }
  dispose() {
    this.Jolt.destroy(this.jolt);
  }
}

// test2 / test8: rod and bob in one static compound whose centre of mass is
// the body's (each child's density gives it its own mass), the mass and
// moments set from the rig, hinged to the world about z at the anchor.
function pendulum(Jolt, bobMass, options) {
  const { ANCHOR_HEIGHT, ROD_LENGTH, ROD_THICKNESS, ROD_MASS, BOB_RADIUS } = scene.test2;
  const rig = pendulumMass(bobMass);
  const world = new World(Jolt, SURFACE_GRAVITY, options);
  const rod = world.box([ROD_LENGTH, ROD_THICKNESS, ROD_THICKNESS]);
  rod.SetDensity(ROD_MASS / (ROD_LENGTH * ROD_THICKNESS * ROD_THICKNESS));
  const bob = world.sphere(BOB_RADIUS);
  bob.SetDensity(bobMass / ((4 / 3) * Math.PI * BOB_RADIUS ** 3));
  const compound = new Jolt.StaticCompoundShapeSettings();
  compound.AddShapeShape(new Jolt.Vec3(rig.rodOffset, 0, 0), Jolt.Quat.prototype.sIdentity(), rod, 0);
  compound.AddShapeShape(new Jolt.Vec3(rig.bobOffset, 0, 0), Jolt.Quat.prototype.sIdentity(), bob, 0);
  const shape = compound.Create().Get();
  const body = world.body(shape, rig.mass, [rig.centre, ANCHOR_HEIGHT, 0], { inertia: rig.inertia });
  const hinge = new Jolt.HingeConstraintSettings();
  hinge.mPoint1 = hinge.mPoint2 = new Jolt.RVec3(0, ANCHOR_HEIGHT, 0);
  hinge.mHingeAxis1 = hinge.mHingeAxis2 = new Jolt.Vec3(0, 0, 1);
  hinge.mNormalAxis1 = hinge.mNormalAxis2 = new Jolt.Vec3(1, 0, 0);
  world.system.AddConstraint(hinge.Create(Jolt.Body.prototype.sFixedToWorld, body));
  return {
    step: () => world.step(),
    centreOfMass: () => world.position(body),
    kineticEnergy: () => kineticEnergy(rig.mass, rig.inertia, world.velocity(body), world.spin(body), world.rotation(body)),
    mass: () => rig.mass,
  };
}

function ball(Jolt, options) {
  const { START_HEIGHT, BALL_RADIUS, BALL_MASS, BOUNCE, GRAVITY_FACTOR } = scene.test9;
  const world = new World(Jolt, GRAVITY_FACTOR * SURFACE_GRAVITY, options);
  world.body(world.plane(), 0, [0, 0, 0], { restitution: BOUNCE });
  const body = world.body(world.sphere(BALL_RADIUS), BALL_MASS, [0, START_HEIGHT, 0], { restitution: BOUNCE });
  return { step: () => world.step(), centre: () => world.position(body) };
}

// test1: Jolt combines restitutions by maximum: the ground's is 0, so each
// contact has the ball's own.
function balls(Jolt, options) {
  const t = scene.test1;
  const world = new World(Jolt, t.GRAVITY_FACTOR * SURFACE_GRAVITY, options);
  world.body(world.plane(), 0, [0, 0, 0], { restitution: 0 });
  const bodies = [], bounces = [];
  for (let i = 0; i < t.BALL_COUNT; ++i) {
    const { position, bounce } = ballLayout(i);
    bodies.push(world.body(world.sphere(t.BALL_RADIUS), t.BALL_MASS, position, { restitution: bounce }));
    bounces.push(bounce);
  }
  return {
    count: bodies.length, bounceVelocity: world.system.GetPhysicsSettings().mMinVelocityForRestitution,
    bounce: (i) => bounces[i], step: () => world.step(), centre: (i) => world.position(bodies[i]),
    speed: (i) => Math.hypot(...world.velocity(bodies[i])),
  };
}

// test6: the 5000 kg cube on a point constraint (a ball joint) 2 m above the
// 1 kg cube resting on the ground plane, every body with test6's no-slip friction.
function axisSystem(Jolt, options) {
  const t = scene.test6;
  const world = new World(Jolt, SURFACE_GRAVITY, options);
  const friction = scene.top.NO_SLIP_FRICTION;
  world.body(world.plane(), 0, [0, 0, 0], { friction });
  const small = world.body(world.box([t.SMALL_SIDE, t.SMALL_SIDE, t.SMALL_SIDE]), t.SMALL_MASS, [0, t.SMALL_SIDE / 2, 0], { friction });
  const big = world.body(world.box([t.BIG_SIDE, t.BIG_SIDE, t.BIG_SIDE]), t.BIG_MASS, [0, t.ANCHOR_HEIGHT + t.BIG_SIDE / 2, 0], { friction });
  const joint = new Jolt.PointConstraintSettings();
  joint.mPoint1 = joint.mPoint2 = new Jolt.RVec3(0, t.ANCHOR_HEIGHT, 0);
  world.system.AddConstraint(joint.Create(small, big));
  return uprightReadout({ step: () => world.step(), position: (b) => world.position(b),
    rotation: (b) => world.rotation(b) }, small, big);
}

// test7: the pivot on a point constraint (a ball joint) to the world, the
// big cube on another to the pivot, the test cube thrown at the pivot; every
// body with test7's no-slip friction (Jolt combines by geometric mean). The
// pivot and the big cube share a collision group that keeps the two from
// colliding with each other, as the ODE programs do for joined bodies.
function hangingPair(Jolt, options) {
  const t = scene.test7;
  const world = new World(Jolt, SURFACE_GRAVITY, options);
  const friction = scene.top.NO_SLIP_FRICTION;
  const pairFilter = new Jolt.GroupFilterTable(2);
  pairFilter.DisableCollision(0, 1);
  const cube = (side) => world.box([side, side, side]);
  world.body(world.plane(), 0, [0, 0, 0], { friction });
  const pivot = world.body(cube(t.PIVOT_SIDE), t.PIVOT_MASS, [0, t.PIVOT_CENTRE_Y, 0],
    { friction, group: new Jolt.CollisionGroup(pairFilter, 0, 0) });
  const big = world.body(cube(t.BIG_SIDE), t.BIG_MASS, [0, t.BIG_CENTRE_Y, 0],
    { friction, group: new Jolt.CollisionGroup(pairFilter, 0, 1) });
  const thrown = world.body(cube(t.TEST_CUBE_SIDE), t.TEST_CUBE_MASS, throwState().position, { friction });
  const top = new Jolt.PointConstraintSettings();
  top.mPoint1 = top.mPoint2 = new Jolt.RVec3(0, t.ANCHOR_HEIGHT, 0);
  world.system.AddConstraint(top.Create(Jolt.Body.prototype.sFixedToWorld, pivot));
  const middle = new Jolt.PointConstraintSettings();
  middle.mPoint1 = middle.mPoint2 = new Jolt.RVec3(0, t.LOWER_ANCHOR_Y, 0);
  world.system.AddConstraint(middle.Create(pivot, big));
  const throwCube = () => {
    const { position, velocity } = throwState();
    world.bodies.SetPositionAndRotation(thrown.GetID(), new Jolt.RVec3(...position), Jolt.Quat.prototype.sIdentity(),
      Jolt.EActivation_Activate);
    world.bodies.SetLinearVelocity(thrown.GetID(), new Jolt.Vec3(...velocity));
    world.bodies.SetAngularVelocity(thrown.GetID(), new Jolt.Vec3(0, 0, 0));
  };
  throwCube();
  return hangingPairReadout({ step: () => world.step(), position: (b) => world.position(b),
    rotation: (b) => world.rotation(b), spin: (b) => world.spin(b) }, pivot, big, thrown, throwCube);
}

// test3: the domino spiral, friction 1.0 (geometric mean: 1.0), sleeping on
// with test3's 0.1 m/s as Jolt's point-velocity threshold (its default 0.03)
// after Jolt's 0.5 s below it.
function dominoes(Jolt, options) {
  const t = scene.test3;
  const world = new World(Jolt, SURFACE_GRAVITY, options);
  const physics = world.system.GetPhysicsSettings();
  physics.mPointVelocitySleepThreshold = t.AUTO_DISABLE_THRESHOLD;
  world.system.SetPhysicsSettings(physics);
  const friction = t.DEFAULT_MU;
  world.body(world.plane(), 0, [0, 0, 0], { friction });
  const bodies = dominoStarts(t.DEFAULT_DOMINOES).map((d) => {
    const body = world.body(world.box([t.DOMINO_THICKNESS, t.DOMINO_HEIGHT, t.DOMINO_WIDTH]), t.DOMINO_MASS, d.centre,
      { friction, rotation: d.rotation, sleeps: true });
    world.bodies.SetLinearVelocity(body.GetID(), new Jolt.Vec3(...d.velocity));
    world.bodies.SetAngularVelocity(body.GetID(), new Jolt.Vec3(...d.spin));
    return body;
  });
  return {
    step: () => world.step(), count: bodies.length, sleeps: true,
    tiltDegrees: (i) => tiltDegrees(world.rotation(bodies[i])),
    activeBodies: () => bodies.filter((b) => b.IsActive()).length,
  };
}

// test5: plates dropped onto the platform, every body with test5's no-slip friction.
function plates(Jolt, options) {
  const t = scene.test5;
  const world = new World(Jolt, SURFACE_GRAVITY, options);
  const friction = scene.top.NO_SLIP_FRICTION;
  world.body(world.box([t.PLATFORM_SIDE, t.PLATFORM_THICKNESS, t.PLATFORM_SIDE]), 0, [0, -t.PLATFORM_THICKNESS / 2, 0], { friction });
  return plateStack(world, (height) => world.body(world.box([t.PLATE_WIDTH, t.PLATE_THICKNESS, t.PLATE_WIDTH]), t.PLATE_MASS,
    [0, height, 0], { friction }));
}

function stack(Jolt, bigMass, options) {
  const t = scene.test4;
  const world = new World(Jolt, SURFACE_GRAVITY, options);
  world.body(world.box([t.PLATFORM_SIDE, t.PLATFORM_THICKNESS, t.PLATFORM_SIDE]), 0, [0, -t.PLATFORM_THICKNESS / 2, 0]);
  const small = world.body(world.box([t.SMALL_SIDE, t.SMALL_SIDE, t.SMALL_SIDE]), t.SMALL_MASS, [0, t.SMALL_SIDE / 2, 0]);
  const big = world.body(world.box([t.BIG_SIDE, t.BIG_SIDE, t.BIG_SIDE]), bigMass, [0, t.BIG_START_HEIGHT, 0]);
  return stackReadout({ step: () => world.step(), position: (b) => world.position(b),
    transform: (b) => [world.position(b), world.rotation(b)] }, small, big);
}

function launch(Jolt, velocity, options) {
  const t = scene.test10;
  const world = new World(Jolt, SURFACE_GRAVITY, options);
  world.body(world.plane(), 0, [0, t.GROUND_Y, 0]);
  world.body(world.box([t.WALL_THICKNESS, t.WALL_HEIGHT, t.WALL_WIDTH]), 0, [t.WALL_X, t.WALL_HEIGHT / 2, 0]);
  const sweep = options.ccd || options.setting === 'best';
  const cube = world.body(world.box([t.CUBE_SIDE, t.CUBE_SIDE, t.CUBE_SIDE]), t.CUBE_MASS,
    [t.LAUNCH_X, t.LAUNCH_Y, t.LAUNCH_Z], { sweep });
  world.bodies.SetLinearVelocity(cube.GetID(), new Jolt.Vec3(velocity, 0, 0));
  return launchedCube(world, cube);
}

function settingText(options) {
  const best = options.setting === 'best';
  let text = `jolt.Step(h, 1), speed caps raised to 1e9, ${options.scene === 'test3' ? '' : 'sleeping off, '}convex radius 0.05 m or the smallest half extent; `;
  text += best ? 'damping 0, 50 velocity / 10 position iterations, restitution at any speed'
    : "Jolt's defaults (damping 0.05 linear and angular, 10 velocity / 2 position iterations, no restitution below 1 m/s)";
  if (options.scene === 'test9') text += '; restitution 1.0 on both bodies (maximum: 1.0), ground a plane';
  if (options.scene === 'test1') text += "; each ball's restitution, the ground's 0 (maximum: the ball's), ground a plane";
  if (options.scene === 'test5') text += '; friction 100 on every body (test5\'s never-sliding contacts)';
  if (options.scene === 'test3') text += '; friction 1.0, sleeping on (point velocity 0.1 m/s for 0.5 s), ground a plane';
  if (options.scene === 'test6') text += '; friction 100 on every body (test6\'s never-sliding contacts)';
  if (options.scene === 'test7') text += '; point constraints (ball joints), friction 100 on every body, ground a plane';
  if (options.scene === 'test10') text += options.ccd || best ? '; cube swept (motion quality LinearCast)' : '; cube not swept (Discrete)';
  return text;
}

module.exports = { name: 'jolt', packageName: 'jolt-physics', hasContinuousCollision: true, load, settingText, plateStack: plates, dominoes, balls, axisSystem, hangingPair, pendulum, ball, stack, launch };
