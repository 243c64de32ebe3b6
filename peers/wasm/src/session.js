'use strict';
// One engine spoken to in the lines of doc/engine-protocol.md: a message in,
// its reply out (or none). The Node.js server (engine_server.js) feeds it
// its stdin's lines; a web page (web/engines/) feeds it the C++ adapter's
// messages directly. Either way the same messages give the same replies.

const REPLYING = new Set(['build', 'add', 'step']);  // the messages that take a reply

// The most steps one message asks for: the program asks for 1 at a time and
// a page for a frame's few; more would hold the server past any reply's deadline.
const MAX_STEPS_PER_MESSAGE = 1000;

// Non-finite numbers are not JSON: a state with NaN or infinity sends null
// in their place, which the C++ side reads back as NaN.
const finiteOrNull = (x) => (Number.isFinite(x) ? x : null);

function statesOf(engine, count) {
  const states = [];
  for (let i = 0; i < count; ++i) {
    const s = engine.state(i);
    states.push(s ? s.map(finiteOrNull) : null);
  }
  return states;
}

class Session {
  // `remake` (optional) makes a fresh engine on the module already loaded:
  // 'reset' uses it, so that R or a rewind in a window empties the engine
  // without a new process and a new WebAssembly module.
  constructor(engine, remake = null) {
    this.engine = engine;
    this.remake = remake;
    this.bodies = 0;
    this.pending = null;  // an error in a message without a reply, told in the next reply
    this.quit = false;
  }

  // A body index the program may name: one of the world's.
  bodyIndex(message) {
    const i = message.body;
    if (!Number.isInteger(i) || i < 0 || i >= this.bodies) throw new Error(`no body ${JSON.stringify(i)} (the world has ${this.bodies})`);
    return i;
  }

  // One message; returns the reply or undefined (a message without one).
  handle(message) {
    const engine = this.engine;
    switch (message.op) {
      case 'build':
        engine.build(message.world, message.removed || []);
        this.bodies = (message.world.bodies || []).length;
        return { ok: true, notes: engine.notes.fresh(), states: statesOf(engine, this.bodies) };
      case 'add':
        engine.add(message.world, message.first_body, message.first_geom, message.first_joint);
        this.bodies = (message.world.bodies || []).length;
        return { ok: true, notes: engine.notes.fresh(), states: statesOf(engine, this.bodies) };
      case 'remove':
        engine.remove(this.bodyIndex(message));
        return undefined;
      case 'set_state':
        engine.setState(this.bodyIndex(message), message.state);
        return undefined;
      case 'reset':
        if (!this.remake) throw new Error('this session cannot make a fresh engine');
        if (typeof engine.dispose === 'function') engine.dispose();
        this.engine = this.remake();
        this.bodies = 0;
        return undefined;
      case 'force':
        engine.applyForce(this.bodyIndex(message), message.force, message.torque);
        return undefined;
      case 'settings':
        engine.changeSettings(message.world);
        return undefined;
      case 'step': {
        const count = message.count === undefined ? 1 : message.count;
        if (!Number.isInteger(count) || count < 1 || count > MAX_STEPS_PER_MESSAGE)
          throw new Error(`count ${JSON.stringify(count)}: a whole number of steps in [1, ${MAX_STEPS_PER_MESSAGE}]`);
        for (let n = 0; n < count; ++n) engine.step();
        return {
          states: statesOf(engine, this.bodies),
          contacts: engine.contactCount(),
          engine_wall_s: engine.wallSeconds(),
          engine_cpu_s: engine.cpuSeconds(),
          notes: engine.notes.fresh(),
        };
      }
      default:
        throw new Error(`unknown op ${JSON.stringify(message.op)}`);
    }
  }

  // Gives the engine's world back to its module (a page runs many sessions
  // on one module): at quit, and by a host that ends a session otherwise.
  dispose() {
    if (this.engine && typeof this.engine.dispose === 'function') this.engine.dispose();
  }

  // One line in; the reply's line, or null for a message that takes none.
  // After 'quit' `quit` is true: the host ends the session.
  line(text) {
    if (!text.trim()) return null;
    let message = null;
    try {
      message = JSON.parse(text);
    } catch (error) {
      this.pending = this.pending || `a message that is not JSON (${error.message})`;
    }
    if (message && message.op === 'quit') {
      this.quit = true;
      this.dispose();
      return null;
    }
    let reply;
    if (message) {
      try {
        reply = this.handle(message);
      } catch (error) {
        const what = `${message.op}: ${error.message}`;
        if (REPLYING.has(message.op)) reply = { error: what };
        else this.pending = this.pending || what;
      }
    }
    if (!(message && REPLYING.has(message.op))) return null;
    if (this.pending) {
      reply = { error: this.pending };
      this.pending = null;
    }
    return JSON.stringify(reply);
  }
}

module.exports = { Session, MAX_STEPS_PER_MESSAGE };
