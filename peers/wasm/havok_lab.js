#!/usr/bin/env node
'use strict';
// havok_lab: the thesis's scenes on Havok's WebAssembly build (doc/peers.md).
// Started again with node's --no-concurrent-recompilation where it lacks it: src/safe_exit.js says why.
if (!require('./src/safe_exit').restartedWithSafeExit(__filename)) {
  require('./src/main').main(require('./src/havok'));
}
