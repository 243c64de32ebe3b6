'use strict';
// test6's measurement (tests/test6_axis_system.cpp), for the web peers: how
// long the 5000 kg cube stays upright on its ball joint (tilt at most 1
// degree, centre within 0.05 m of where it was built), with test6's metric
// names. `model`: {step(), bigCentre(), bigTiltDegrees(), smallSink()}.
const { scene } = require('./constants');
const { stepsFor } = require('./measurements');

function measureUpright(model, options, metrics) {
  const t = scene.test6;
  const built = model.bigCentre();
  let tilt = model.bigTiltDegrees(), maxTilt = tilt, maxSideways = 0, maxSink = 0, uprightUntil = -1;
  const tally = { steps: 0, finite: true };
  for (let n = stepsFor(options); tally.steps < n;) {
    model.step();
    const p = model.bigCentre();
    tilt = model.bigTiltDegrees();
    if (!p.every(Number.isFinite) || !Number.isFinite(tilt)) {
      tally.finite = false;
      break;
    }
    ++tally.steps;
    const sideways = Math.hypot(p[0] - built[0], p[2] - built[2]);
    maxTilt = Math.max(maxTilt, tilt);
    maxSideways = Math.max(maxSideways, sideways);
    if (uprightUntil < 0) maxSink = Math.max(maxSink, model.smallSink());
    if (uprightUntil < 0 && (tilt > t.UPRIGHT_TILT_DEGREES || sideways > t.UPRIGHT_SIDEWAYS_METRES))
      uprightUntil = tally.steps * options.step;
  }
  metrics.set('seconds_upright', uprightUntil < 0 ? tally.steps * options.step : uprightUntil);
  metrics.set('fell', uprightUntil < 0 ? 0 : 1);
  metrics.set('max_tilt_degrees', maxTilt);
  metrics.set('final_tilt_degrees', tilt);
  metrics.set('max_sideways_metres', maxSideways);
  metrics.set('sink_while_upright_metres', maxSink);
  metrics.set('start_tilt_degrees', 0);
  metrics.set('max_angular_speed_limit', 0);
  return tally;
}

module.exports = { measureUpright };
