'use strict';
// A web page loads each engine's module once and starts a session on it for
// every reset, rewind or compare start: each session must free its world
// when it ends (quit), or a module runs out of memory after a few (Jolt's
// did at the seventh). 100 sessions on one module, per engine, each built,
// stepped and quit as the page does it; and the module's memory after the
// last is no larger than after the tenth (a WebAssembly memory never
// shrinks, so growth past the tenth session is a leak).
//   node --test peers/wasm/test/
const test = require('node:test');
const assert = require('node:assert');
const fs = require('fs');
const path = require('path');
const { Session } = require('../src/session');

const WORLD = JSON.parse(fs.readFileSync(path.join(__dirname, '..', '..', '..', 'doc', 'worlds', 'newtons_cradle.json'), 'utf8'));
delete WORLD.measures;
const SESSIONS = 100;

// The bytes of a loaded module's WebAssembly memory, where the module shows it.
function memoryBytes(module) {
  for (const key of ['HEAP8', 'HEAPU8', 'wasmMemory']) {
    let view;
    try {
      view = module && module[key];
    } catch {  // PhysX's build aborts on a runtime name it did not export
      continue;
    }
    if (view && view.buffer) return view.buffer.byteLength;
  }
  return null;
}

for (const name of require('../src/engines/names')) {
  test(`${SESSIONS} sessions on one ${name} module each free their world`, async () => {
    const adapter = require(`../src/engines/${name}`);
    const wasmBinary = adapter.wasmFile ? fs.readFileSync(require.resolve(adapter.wasmFile)) : undefined;
    const module = await adapter.load({ wasmBinary });
    let afterTenth = null;
    for (let i = 0; i < SESSIONS; ++i) {
      const session = new Session(adapter.make(module, 'default'));
      const built = JSON.parse(session.line(JSON.stringify({ op: 'build', world: WORLD, removed: [] })));
      assert.strictEqual(built.ok, true, `session ${i + 1}: ${JSON.stringify(built)}`);
      const stepped = JSON.parse(session.line(JSON.stringify({ op: 'step', count: 10 })));
      assert.ok(Array.isArray(stepped.states), `session ${i + 1}: ${JSON.stringify(stepped)}`);
      session.line(JSON.stringify({ op: 'quit' }));
      assert.strictEqual(session.quit, true);
      if (i === 9) afterTenth = memoryBytes(module);
    }
    const last = memoryBytes(module);
    if (afterTenth !== null && last !== null)
      assert.ok(last <= afterTenth, `${name}'s memory grew from ${afterTenth} to ${last} bytes after the tenth session`);
  });
}
