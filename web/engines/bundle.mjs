// Bundles web/engines/index.js and the engines it loads into a folder of
// the site (scripts/web/build.sh): an ES module index.js, one chunk per
// engine, Havok's .wasm file beside them, and engines.json, each engine's
// version, which the index page reads.
//   node web/engines/bundle.mjs OUT
import { build } from "esbuild";
import { readFileSync, writeFileSync } from "node:fs";
import { createRequire } from "node:module";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const packages = resolve(here, "../../peers/wasm/node_modules");
const out = process.argv[2];
if (!out) {
  console.error("usage: node web/engines/bundle.mjs OUT");
  process.exit(2);
}

// Each engine's npm package as its adapter names it (loading an adapter
// loads no engine: that waits for its load()).
const require = createRequire(import.meta.url);
const versions = {};
for (const name of require("../../peers/wasm/src/engines/names.js")) {
  const { packageName } = require(`../../peers/wasm/src/engines/${name}.js`);
  versions[name] = JSON.parse(readFileSync(join(packages, packageName, "package.json"), "utf8")).version;
}

await build({
  entryPoints: [join(here, "index.js")],
  outdir: out,
  bundle: true,
  splitting: true,
  format: "esm",
  platform: "browser",
  target: "es2020",
  minify: true,
  logLevel: "warning",
  nodePaths: [packages],
  define: { ODELAB_ENGINE_VERSIONS: JSON.stringify(versions) },
  loader: { ".wasm": "file" },
  // Emscripten's glue names Node's modules in branches a page never takes.
  external: ["fs", "path", "crypto", "url", "module", "worker_threads", "perf_hooks", "util", "node:*"],
});
writeFileSync(join(out, "engines.json"), JSON.stringify(versions) + "\n");
