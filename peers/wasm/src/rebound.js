'use strict';
// test1's measurement (tests/test1_jumping_balls.cpp), for the web peers:
// fifty balls, ball i with restitution i/49, dropped on the ground; per ball
// the first two rebound apexes above the contact height, whose ratio is e^2
// for an exact restitution. Same metric names and definitions as test1.
// `balls`: {count, bounce(i), step(), centre(i), speed(i)}.
const { scene } = require('./constants');
const { ApexTracker } = require('./apex');
const { stepsFor } = require('./measurements');

function measureRebounds(balls, options, metrics) {
  const t = scene.test1;
  const records = [];
  for (let i = 0; i < balls.count; ++i) {
    const tracker = new ApexTracker();
    tracker.restart(0, balls.centre(i));
    records.push({ bounce: balls.bounce(i), tracker, apex: [NaN, NaN] });
  }
  const tally = { steps: 0, finite: true };
  for (let n = stepsFor(options); tally.steps < n;) {
    balls.step();
    ++tally.steps;
    records.forEach((record, i) => {
      const c = balls.centre(i);
      if (!c.every(Number.isFinite)) tally.finite = false;
      const apex = record.tracker.update(tally.steps * options.step, c);
      if (apex && record.tracker.count <= 2) record.apex[record.tracker.count - 1] = apex.position[1] - t.BALL_RADIUS;
    });
    if (!tally.finite) break;
  }
  const measured = (r) => r.bounce >= t.MEASURED_FROM_BOUNCE && Number.isFinite(r.apex[1]);
  const error = (r) => Math.abs(r.apex[1] / r.apex[0] - r.bounce * r.bounce);
  let worst = -1;
  records.forEach((r, i) => { if (measured(r) && (worst < 0 || error(r) > error(records[worst]))) worst = i; });
  let resting = 0, lowest = Infinity;
  for (let i = 0; i < balls.count; ++i) {
    const height = balls.centre(i)[1] - t.BALL_RADIUS;
    if (balls.speed(i) < t.REST_SPEED && height < t.REST_CLEARANCE) ++resting;
    lowest = Math.min(lowest, height);
  }
  metrics.set('bounce_velocity', balls.bounceVelocity);
  metrics.set('max_rebound_error', worst >= 0 ? error(records[worst]) : NaN);
  metrics.set('worst_ball', worst >= 0 ? worst : NaN);
  metrics.set('balls_measured', records.filter(measured).length);
  metrics.set('balls_bounced', records.filter((r) => r.tracker.count > 0).length);
  metrics.set('balls_at_rest', resting);
  metrics.set('lowest_ball_m', lowest);
  return tally;
}

// Where ball i starts, and its restitution.
function ballLayout(i) {
  const t = scene.test1;
  return { position: [(i - 0.5 * (t.BALL_COUNT - 1)) * t.SPACING, t.DROP_HEIGHT, 0], bounce: i / (t.BALL_COUNT - 1) };
}

module.exports = { measureRebounds, ballLayout };
