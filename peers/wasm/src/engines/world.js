'use strict';
// The world file as the engine server receives it (doc/world-format.md,
// written by odelab::world::worldToJson and validated in C++), and what every
// adapter asks of it: the surface two geoms touch with, whether they touch
// at all, the shapes' and bodies' fields with their defaults.

const INFINITY_TEXT = { infinity: Infinity, '-infinity': -Infinity };

// JSON has no infinity: the world writes the string "infinity".
function num(value, fallback) {
  if (value === undefined || value === null) return fallback;
  if (typeof value === 'string' && value in INFINITY_TEXT) return INFINITY_TEXT[value];
  return value;
}

function readBody(b) {
  const ad = b.auto_disable || {};
  return {
    mass: b.mass,
    inertia: b.inertia,
    position: b.position,
    orientation: b.orientation || [1, 0, 0, 0],
    linearVelocity: b.linear_velocity || [0, 0, 0],
    angularVelocity: b.angular_velocity || [0, 0, 0],
    enabled: b.enabled !== false,
    kinematic: b.kinematic === true,
    gravity: b.gravity !== false,
    maxAngularSpeed: num(b.max_angular_speed, Infinity),
    autoDisable: {
      on: ad.on === true,
      linearThreshold: num(ad.linear_threshold, 0.01),
      angularThreshold: num(ad.angular_threshold, 0.01),
      steps: num(ad.steps, 10),
      time: num(ad.time, 0),
    },
  };
}

function readGeom(g) {
  const size = g.shape === 'box' ? g.size : [g.radius, num(g.length, 0), 0];
  return {
    shape: g.shape,
    size,
    plane: g.plane || [0, 1, 0, 0],
    body: g.body === undefined ? -1 : g.body,
    position: g.position || [0, 0, 0],
    orientation: g.orientation || [1, 0, 0, 0],
    category: num(g.category, 0xffffffff) >>> 0,
    collide: num(g.collide, 0xffffffff) >>> 0,
  };
}

function readJoint(j) {
  return {
    type: j.type,
    body1: j.body1 === undefined ? -1 : j.body1,
    body2: j.body2 === undefined ? -1 : j.body2,
    anchor: j.anchor || [0, 0, 0],
    axis: j.axis || [0, 0, 1],
    lowStop: num(j.low_stop, -Infinity),
    highStop: num(j.high_stop, Infinity),
    erp: num(j.erp, NaN),
    cfm: num(j.cfm, NaN),
  };
}

function readSurface(s) {
  const bounce = s.restitution !== undefined;
  return {
    mu: num(s.mu, Infinity),
    bounce,
    restitution: bounce ? s.restitution : 0,
    bounceVelocity: bounce ? num(s.bounce_velocity, 0) : 0,
    softErp: s.soft_erp,
    softCfm: s.soft_cfm,
    approx1: s.friction_pyramid === true,
  };
}

function readSettings(s) {
  return {
    step: s.step,
    gravity: s.gravity,
    erp: num(s.erp, 0.2),
    cfm: num(s.cfm, 1e-5),
    solver: s.solver || 'quick',
    iterations: num(s.iterations, 20),
    contactMaxCorrectingVelocity: num(s.contact_max_correcting_velocity, Infinity),
    contactSurfaceLayer: num(s.contact_surface_layer, 0),
    maxContacts: num(s.max_contacts, 16),
  };
}

const pairKey = (a, b) => (a < b ? a * 0x100000 + b : b * 0x100000 + a);

// One world as the adapters read it. `removed`: body indices the program
// had removed before this message (their geoms and joints are not built).
class World {
  constructor(json, removed = []) {
    this.settings = readSettings(json.settings);
    this.bodies = (json.bodies || []).map(readBody);
    this.geoms = json.geoms.map(readGeom);
    this.joints = (json.joints || []).map(readJoint);
    this.surfaces = json.surfaces.map(readSurface);
    this.defaultSurface = json.default_surface || 0;
    this.pairs = new Map();
    for (const p of json.pair_surfaces || []) this.pairs.set(pairKey(p.geoms[0], p.geoms[1]), p.surface);
    this.removed = new Set(removed);
    this.joined = new Set();
    for (const j of this.joints)
      if (j.body1 >= 0 && j.body2 >= 0) this.joined.add(pairKey(j.body1, j.body2));
  }
  surfaceIndex(g1, g2) {
    const s = this.pairs.get(pairKey(g1, g2));
    return s === undefined ? this.defaultSurface : s;
  }
  surfaceBetween(g1, g2) {
    return this.surfaces[this.surfaceIndex(g1, g2)];
  }
  // ODE's rule: either geom's category meets the other's collide bits.
  bitsTouch(g1, g2) {
    const a = this.geoms[g1], b = this.geoms[g2];
    return ((a.category & b.collide) >>> 0) !== 0 || ((b.category & a.collide) >>> 0) !== 0;
  }
  mayTouch(g1, g2) {
    const a = this.geoms[g1], b = this.geoms[g2];
    if (a.body < 0 && b.body < 0) return false;
    if (a.body === b.body) return false;
    if (!this.bitsTouch(g1, g2)) return false;
    if (a.body >= 0 && b.body >= 0 && this.joined.has(pairKey(a.body, b.body))) return false;
    return true;
  }
  // Whether some pair of geoms in the world is kept apart by collide bits
  // alone (the engines need a filter only then).
  hasCollideBits() {
    return this.geoms.some((g) => g.category !== 0xffffffff || g.collide !== 0xffffffff);
  }
  // The geoms of body i, by index.
  geomsOf(body) {
    const list = [];
    this.geoms.forEach((g, i) => { if (g.body === body) list.push(i); });
    return list;
  }
  // Every surface some pair of geoms may touch with (indices), for the
  // settings that are global in an engine.
  surfacesInUse() {
    const used = new Set([this.defaultSurface]);
    for (const s of this.pairs.values()) used.add(s);
    return [...used].map((i) => this.surfaces[i]);
  }
}

module.exports = { World, num, pairKey };
