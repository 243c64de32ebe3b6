#!/usr/bin/env node
'use strict';
// Every case of checks/file_rules.json through the web peers' writer and
// reader (src/files.js), then the one case the table cannot state: a link
// planted at the writer's temporary name is never followed.
// Usage: node test/file_rules.test.js [RULES.json]   Exit 0: every case held.
const assert = require('assert');
const crypto = require('crypto');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { execFileSync } = require('child_process');
const { FileRefused, checkWritable, writeAtomically, readBounded } = require('../src/files');

const RULES = process.argv[2] || path.join(__dirname, '..', '..', '..', 'checks', 'file_rules.json');
const READ_LIMIT = 4096;  // the limit the reader cases are read with
const isRoot = process.getuid && process.getuid() === 0;

const rules = JSON.parse(fs.readFileSync(RULES, 'utf8'));
let failed = 0, ran = 0, skipped = 0;

function freshFolder() {
  return fs.mkdtempSync(path.join(os.tmpdir(), 'file_rules_js-'));
}

// Builds what the setup names in `folder`; returns the target and a function
// asserting what must hold afterwards whatever the writer did.
function writerSetup(setup, folder) {
  const target = path.join(folder, 'target.json');
  const victim = path.join(folder, 'victim');
  const keepsVictim = () => assert.strictEqual(fs.readFileSync(victim, 'utf8'), 'precious', 'the victim changed');
  switch (setup) {
    case 'absent': return { target, after: () => {} };
    case 'regular': fs.writeFileSync(target, 'old'); return { target, after: () => {} };
    case 'symlink_to_regular':
      fs.writeFileSync(victim, 'precious');
      fs.symlinkSync('victim', target);
      return { target, after: () => { keepsVictim(); assert(fs.lstatSync(target).isSymbolicLink()); } };
    case 'dangling_symlink':
      fs.symlinkSync('victim', target);
      return { target, after: () => assert(!fs.existsSync(victim), 'the dangling link was followed') };
    case 'hardlink':
      fs.writeFileSync(victim, 'precious');
      fs.linkSync(victim, target);
      return { target, after: () => { keepsVictim(); assert.strictEqual(fs.statSync(target).nlink, 2); } };
    case 'fifo':
      execFileSync('mkfifo', [target]);
      return { target, after: () => assert(fs.lstatSync(target).isFIFO(), 'the FIFO was replaced') };
    case 'char_device':
      execFileSync('mknod', [target, 'c', '1', '3']);
      return { target, after: () => assert(fs.lstatSync(target).isCharacterDevice(), 'the device was replaced') };
    case 'folder':
      fs.mkdirSync(target);
      return { target, after: () => assert.deepStrictEqual(fs.readdirSync(target), []) };
    case 'missing_folder': {
      const missing = path.join(folder, 'missing');
      return { target: path.join(missing, 'target.json'), after: () => assert(!fs.existsSync(missing), 'the folder was made') };
    }
    case 'long_name':
      return { target: path.join(folder, 'n'.repeat(250)), after: () => {} };
    case 'read_only_folder': {
      const locked = path.join(folder, 'locked');
      fs.mkdirSync(locked, 0o555);
      return { target: path.join(locked, 'target.json'), after: () => assert.deepStrictEqual(fs.readdirSync(locked), []) };
    }
    default: throw new Error(`no setup ${setup}`);
  }
}

function readerSetup(setup, folder) {
  const file = path.join(folder, 'input');
  switch (setup) {
    case 'regular': fs.writeFileSync(file, 'ok\n'); return file;
    case 'absent': return file;
    case 'folder': fs.mkdirSync(file); return file;
    case 'fifo': execFileSync('mkfifo', [file]); return file;
    case 'dev_zero': return '/dev/zero';
    case 'oversized': fs.writeFileSync(file, ''); fs.truncateSync(file, READ_LIMIT + 1); return file;
    default: throw new Error(`no setup ${setup}`);
  }
}

function refusedWith(action, why) {
  try {
    action();
  } catch (error) {
    assert(error instanceof FileRefused, `not a refusal: ${error.message}`);
    assert(error.message.includes(why), `"${error.message}" does not say "${why}"`);
    return error.message;
  }
  assert.fail(`not refused (expected "${why}")`);
}

// Nothing of the writer's may be left in the folder: only the setup's names.
function noTemporaryLeft(folder) {
  const left = fs.readdirSync(folder).filter((name) => name.endsWith('.tmp'));
  assert.deepStrictEqual(left, [], 'a temporary file was left');
}

function runCase(kind, c, body) {
  if ((c.root_only && !isRoot) || (c.not_root && isRoot)) {
    console.log(`skipped ${kind} ${c.name}: ${c.root_only ? 'needs root' : 'root bypasses it'}`);
    ++skipped;
    return;
  }
  const folder = freshFolder();
  ++ran;
  try {
    const said = body(folder);
    console.log(`ok ${kind} ${c.name}${said ? `: ${said}` : ''}`);
  } catch (error) {
    ++failed;
    console.log(`FAILED ${kind} ${c.name}: ${error.message}`);
  } finally {
    fs.chmodSync(folder, 0o700);
    for (const name of fs.readdirSync(folder)) {
      try { fs.chmodSync(path.join(folder, name), 0o700); } catch (_) { /* a dangling link */ }
    }
    fs.rmSync(folder, { recursive: true, force: true });
  }
}

for (const c of rules.writer) {
  runCase('writer', c, (folder) => {
    const { target, after } = writerSetup(c.setup, folder);
    let said;
    if (c.expect === 'written') {
      checkWritable(target);
      writeAtomically(target, 'new');
      assert.strictEqual(fs.readFileSync(target, 'utf8'), 'new');
      assert(fs.lstatSync(target).isFile());
    } else {
      // The check before the run refuses it, and so does the write itself.
      said = refusedWith(() => checkWritable(target), c.why);
      refusedWith(() => writeAtomically(target, 'new'), c.why);
    }
    after();
    noTemporaryLeft(folder);
    return said;
  });
}

for (const c of rules.reader) {
  runCase('reader', c, (folder) => {
    const file = readerSetup(c.setup, folder);
    if (c.expect === 'read') {
      assert.strictEqual(readBounded(file, READ_LIMIT).toString('utf8'), 'ok\n');
      return undefined;
    }
    return refusedWith(() => readBounded(file, READ_LIMIT), c.why);
  });
}

// A link planted at the temporary name the writer draws first: the writer
// never opens it (exclusive create), draws another name, and the link and
// its victim are left as they were.
runCase('writer', { name: 'link_planted_at_the_temporary_name' }, (folder) => {
  const target = path.join(folder, 'm.json');
  const victim = path.join(folder, 'victim');
  fs.writeFileSync(victim, 'precious');
  const drawn = Buffer.from('0123456789abcdef', 'hex');
  const planted = path.join(folder, `.m.json.${drawn.toString('hex')}.tmp`);
  fs.symlinkSync('victim', planted);
  const realRandomBytes = crypto.randomBytes;
  let draws = 0;
  crypto.randomBytes = (n) => (++draws === 1 ? drawn.subarray(0, n) : realRandomBytes(n));
  try {
    writeAtomically(target, 'new');
  } finally {
    crypto.randomBytes = realRandomBytes;
  }
  assert(draws >= 2, 'the planted name was not the first drawn');
  assert.strictEqual(fs.readFileSync(victim, 'utf8'), 'precious', 'the write went through the planted link');
  assert(fs.lstatSync(planted).isSymbolicLink(), 'the planted link was removed or replaced');
  assert.strictEqual(fs.readFileSync(target, 'utf8'), 'new');
  assert(fs.lstatSync(target).isFile());
  return 'written beside it, the link and its victim untouched';
});

console.log(`${ran} cases run, ${skipped} skipped, ${failed} failed (rules: ${RULES})`);
process.exitCode = failed ? 1 : 0;
