// The list of scenes, from scenes.json (written by the build from
// tests/scenes/scenes.txt: each scene's name and title), each with a link
// that runs it side by side on the web engines where the site has them
// (engines/engines.json, written by scripts/web/build.sh: their versions,
// none when the site was built without them).

// "Havok, Jolt, Rapier and PhysX" from the engines' names (a name written
// otherwise than capitalized is in TITLES).
const TITLES = { physx: "PhysX" };
function spoken(names) {
  const words = names.map((name) => TITLES[name] || name.charAt(0).toUpperCase() + name.slice(1));
  return words.length < 2 ? words.join("") : words.slice(0, -1).join(", ") + " and " + words[words.length - 1];
}

function sceneLink(address, text) {
  const link = document.createElement("a");
  link.href = address;
  link.textContent = text;
  return link;
}

Promise.all([
  fetch("scenes.json").then((response) => response.json()),
  fetch("engines/engines.json").then((response) => (response.ok ? response.json() : {}), () => ({})),
]).then(([scenes, engines]) => {
  const compared = Object.keys(engines);
  const list = document.getElementById("scenes");
  for (const scene of scenes) {
    const item = document.createElement("li");
    const address = "scene.html?scene=" + encodeURIComponent(scene.name);
    item.appendChild(sceneLink(address, scene.name + " - " + scene.title));
    if (compared.length > 0) {
      item.append(" \u00b7 ");
      item.appendChild(sceneLink(address + "&compare=" + compared.join(","), "beside " + spoken(compared)));
    }
    list.appendChild(item);
  }
});
