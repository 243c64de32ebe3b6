// Opens the site's pages in headless Chromium, the way a visitor does, and
// checks what they load: every page names an icon (link rel="icon") that
// the site serves as an image, every file a page refers to (its links,
// scripts, styles, icon) is there, and nothing the page asked for was
// refused (no 404 in the console, /favicon.ico included).
//
//   node web/check-pages.mjs --site DIR [--scene testN]
//
// The scene page runs SCENE (default test0) for half a simulated second.
// Prints each problem; exits 0 when there is none, 1 otherwise, 2 for bad
// usage.
import { existsSync } from "node:fs";
import { resolve } from "node:path";
import { serveSite, launchChromium, watchProblems } from "./site.mjs";

const options = { scene: "test0" };
{
  const argv = process.argv.slice(2);
  for (let i = 0; i < argv.length; i += 2) {
    const name = argv[i].replace(/^--/, "");
    if (!["site", "scene"].includes(name) || i + 1 >= argv.length) {
      console.error(`error: bad argument '${argv[i]}'\nusage: node check-pages.mjs --site DIR [--scene testN]`);
      process.exit(2);
    }
    options[name] = argv[i + 1];
  }
}
const site = resolve(options.site || "");
if (!options.site || !existsSync(resolve(site, "index.html"))) {
  console.error(`error: ${site} holds no index.html (build it with scripts/odelab.sh web)`);
  process.exit(2);
}

const server = await serveSite(site);
const chromium = await launchChromium();
const base = `http://127.0.0.1:${server.port}/`;
const pages = [
  { path: "index.html", ready: () => document.querySelectorAll("#scenes a").length > 0 },
  { path: `scene.html?scene=${options.scene}&seconds=0.5&width=400&height=300`,
    ready: () => window.odelabRun && window.odelabRun.ended },
];
const problems = [];
try {
  for (const { path, ready } of pages) {
    const page = await chromium.browser.newPage();
    const seen = watchProblems(page);
    await page.goto(base + path);
    await page.waitForFunction(ready, { timeout: 120000, polling: 250 });
    // A browser asks for an icon after the page has loaded.
    await new Promise((done) => setTimeout(done, 1000));
    const found = await page.evaluate(async () => {
      const icon = document.querySelector('link[rel~="icon"]');
      const referred = Array.from(document.querySelectorAll("link[href], script[src], img[src], a[href]"))
        .map((element) => new URL(element.getAttribute("href") || element.getAttribute("src"), location.href))
        .filter((url) => url.origin === location.origin)
        .map((url) => url.origin + url.pathname);
      const missing = [];
      for (const url of new Set(referred)) {
        const response = await fetch(url);
        if (!response.ok) missing.push(`${response.status} ${url}`);
      }
      let iconType = null;
      if (icon) {
        const response = await fetch(icon.href);
        iconType = response.ok ? response.headers.get("Content-Type") : `status ${response.status}`;
      }
      return { icon: icon && icon.getAttribute("href"), iconType, missing };
    });
    const say = (text) => problems.push(`${path}: ${text}`);
    if (!found.icon) say('no icon (link rel="icon")');
    else if (!/^image\//.test(found.iconType || "")) say(`its icon ${found.icon} is not served as an image (${found.iconType})`);
    for (const entry of found.missing) say(`refers to a missing file: ${entry}`);
    for (const entry of seen.missing) say(`a request was refused: ${entry}`);
    for (const entry of seen.consoleErrors) say(`console error: ${entry}`);
    console.log(`${path}: icon ${found.icon} (${found.iconType}), ${seen.missing.length} refused requests, ` +
                `${seen.consoleErrors.length} console errors`);
    await page.close();
  }
} catch (error) {
  problems.push(String(error));
} finally {
  await chromium.close();
  server.close();
}
for (const problem of problems) console.log(`FAIL ${problem}`);
process.exit(problems.length === 0 ? 0 : 1);
