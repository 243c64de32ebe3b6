'use strict';
// A Jolt physics system with two object layers, static and moving, where
// moving bodies meet both and static ones only moving ones: what the
// adapter (jolt.js) and the bare harness (bench/bare.js) both start from,
// so the harness times the same system the adapter builds.

const STATIC = 0, MOVING = 1;  // object layers

// The JoltInterface for module J; its settings object is freed once used.
function joltInterface(J) {
  const settings = new J.JoltSettings();
  const pairs = new J.ObjectLayerPairFilterTable(2);
  pairs.EnableCollision(STATIC, MOVING);
  pairs.EnableCollision(MOVING, MOVING);
  const layers = new J.BroadPhaseLayerInterfaceTable(2, 2);
  layers.MapObjectToBroadPhaseLayer(STATIC, new J.BroadPhaseLayer(0));
  layers.MapObjectToBroadPhaseLayer(MOVING, new J.BroadPhaseLayer(1));
  settings.mObjectLayerPairFilter = pairs;
  settings.mBroadPhaseLayerInterface = layers;
  settings.mObjectVsBroadPhaseLayerFilter = new J.ObjectVsBroadPhaseLayerFilterTable(layers, 2, pairs, 2);
  const iface = new J.JoltInterface(settings);
  J.destroy(settings);
  return iface;
}

module.exports = { STATIC, MOVING, joltInterface };
