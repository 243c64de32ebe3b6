#!/usr/bin/env node
'use strict';
// havok_lab: the thesis's scenes on Havok's WebAssembly build (doc/peers.md).
require('./src/main').main(require('./src/havok'));
