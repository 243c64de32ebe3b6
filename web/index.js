// The list of scenes, from scenes.json (written by the build from
// tests/scenes/scenes.txt: each scene's name and title).
fetch("scenes.json")
  .then((response) => response.json())
  .then((scenes) => {
    const list = document.getElementById("scenes");
    for (const scene of scenes) {
      const item = document.createElement("li");
      const link = document.createElement("a");
      link.href = "scene.html?scene=" + encodeURIComponent(scene.name);
      link.textContent = scene.name + " - " + scene.title;
      item.appendChild(link);
      list.appendChild(item);
    }
  });
