'use strict';
// The engine server's bounds (doc/engine-protocol.md): a step message asks
// for at most MAX_STEPS_PER_MESSAGE steps, and a message line longer than
// its bound ends the reading instead of filling memory.
//   node --test peers/wasm/test/bounds.test.js
const test = require('node:test');
const assert = require('node:assert');
const { PassThrough } = require('node:stream');
const { Session, MAX_STEPS_PER_MESSAGE } = require('../src/session');
const { readLines } = require('../src/line_reader');

// An engine that only counts its steps: the session's rules, not physics.
function countingEngine() {
  return {
    steps: 0,
    step() { this.steps += 1; },
    state() { return [0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1]; },
    contactCount() { return 0; },
    wallSeconds() { return 0; },
    cpuSeconds() { return 0; },
    notes: { fresh: () => [] },
  };
}

test('a step count past the bound, or not a whole number, is refused without stepping', () => {
  const engine = countingEngine();
  const s = new Session(engine);
  for (const count of [1e9, MAX_STEPS_PER_MESSAGE + 1, 0, -3, 2.5, '10']) {
    const reply = JSON.parse(s.line(JSON.stringify({ op: 'step', count })));
    assert.match(reply.error, /^step: count .*: a whole number of steps in \[1, \d+\]/, JSON.stringify(count));
  }
  assert.strictEqual(engine.steps, 0);
  assert.ok(JSON.parse(s.line(JSON.stringify({ op: 'step', count: MAX_STEPS_PER_MESSAGE }))).states);
  assert.strictEqual(engine.steps, MAX_STEPS_PER_MESSAGE);
});

function feed(chunks, maxBytes) {
  return new Promise((resolve) => {
    const stream = new PassThrough();
    const lines = [];
    readLines(stream, maxBytes, {
      line: (l) => lines.push(l),
      tooLong: (bytes) => resolve({ lines, tooLong: bytes }),
      end: () => resolve({ lines, tooLong: 0 }),
    });
    for (const c of chunks) stream.write(c);
    stream.end();
  });
}

test('lines split across chunks and CRLF come out whole', async () => {
  const got = await feed(['{"op":', '"step"}\r\n{"op"', ':"quit"}\n', 'last'], 100);
  assert.deepStrictEqual(got.lines, ['{"op":"step"}', '{"op":"quit"}', 'last']);
  assert.strictEqual(got.tooLong, 0);
});

test('a line past the bound stops the reading at the bound, not at its end', async () => {
  const chunk = 'x'.repeat(1000);
  const got = await feed(['ok\n', ...Array(50).fill(chunk), '\n'], 4000);
  assert.deepStrictEqual(got.lines, ['ok']);
  assert.ok(got.tooLong > 4000 && got.tooLong <= 5000, `stopped after ${got.tooLong} bytes`);
});

test('a 64 MB line in 64 KiB chunks is read in one pass (figure printed)', async () => {
  const chunk = Buffer.alloc(65536, 0x78);
  const chunks = Array(1024).fill(chunk);
  const start = process.hrtime.bigint();
  const got = await feed([...chunks, '\n'], 128 * 1024 * 1024);
  const seconds = Number(process.hrtime.bigint() - start) / 1e9;
  assert.strictEqual(got.lines[0].length, 64 * 1024 * 1024);
  console.log(`# a 64 MiB line read in ${seconds.toFixed(2)} s`);
});
