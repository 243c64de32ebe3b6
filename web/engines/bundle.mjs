// Bundles web/engines/index.js and the engines it loads into a folder of
// the site (scripts/web/build.sh): an ES module index.js, one chunk per
// engine, Havok's .wasm file beside them, and engines.json, each engine's
// version, which the index page reads.
//   node web/engines/bundle.mjs OUT
import { build } from "esbuild";
import { readFileSync, writeFileSync } from "node:fs";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const packages = resolve(here, "../../peers/wasm/node_modules");
const out = process.argv[2];
if (!out) {
  console.error("usage: node web/engines/bundle.mjs OUT");
  process.exit(2);
}

const PACKAGES = { havok: "@babylonjs/havok", jolt: "jolt-physics", rapier: "@dimforge/rapier3d-compat" };
const versions = {};
for (const [name, pkg] of Object.entries(PACKAGES))
  versions[name] = JSON.parse(readFileSync(join(packages, pkg, "package.json"), "utf8")).version;

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
