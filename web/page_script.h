#pragma once
// The page's own script and style (viewer/functionlab-page.js, page.css).
//
// The script loads the scene from scene.js (gzipped, as base64) rather than
// letting X_ITE fetch scene.x3d: a page opened from the file system may not fetch, nor import()
// X_ITE's components, nor load the style sheet X_ITE links into its canvas.
// So it gives X_ITE the style itself, marks the components the page loaded
// with <script> tags as present, and starts each baked TimeSensor by its clock
// (the scene's when the page opened; a wall clock's in the reader's zone).
// When the world is shown it sets body[data-ready], which the browser tests
// wait for; ?shot shows the canvas alone, filling the window, and ?still
// stops time at the scene's moment 0.

namespace fl::web {

inline constexpr const char* kPageScript = R"js("use strict";
(function () {
  const page = window.FunctionLabScene;

  function styleCanvas(canvas) {
    const root = canvas.shadowRoot;
    if (!root || !window.FunctionLabXiteCss) return;
    const style = document.createElement("style");
    style.textContent = window.FunctionLabXiteCss;
    // A picture for the tests: X_ITE's buttons and notices left out.
    if (document.body.classList.contains("shot"))
      style.textContent +=
        "\n.x_ite-private-buttons, .x_ite-private-notification { display: none !important; }";
    root.appendChild(style);
    const browser = root.querySelector(".x_ite-private-browser");
    if (browser) browser.style.display = "";
  }

  function startTime(clock) {
    switch (clock.base) {
      case "utc": return clock.start;
      // The frames show the local time at a UTC offset of 0; here it is
      // UTC minus getTimezoneOffset() minutes.
      case "local": return clock.start + new Date().getTimezoneOffset() * 60;
      // X3D time is seconds since 1970, as Date gives it.
      default: return Date.now() / 1000 + clock.start;
    }
  }

  // The scene's TimeSensors that have names (a ROUTE needs one to drive anything).
  function timeSensors(scene) {
    return Array.from(scene.namedNodes).filter(n => n.getNodeTypeName() === "TimeSensor");
  }
  window.FunctionLabTimeSensors = () =>
    timeSensors(X3D.getBrowser(document.getElementById("scene")).currentScene);

  async function sceneText() {
    const bytes = Uint8Array.from(atob(page.x3dGzipBase64), c => c.charCodeAt(0));
    const text = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"));
    return await new Response(text).text();
  }

  async function start() {
    if (!page || !window.X3D) throw new Error("the page's files are incomplete");
    const canvas = document.getElementById("scene");
    const browser = X3D.getBrowser(canvas);
    styleCanvas(canvas);
    for (const name of page.components) {
      const c = browser.getSupportedComponents().get(name);
      if (c)
        browser.updateSupportedComponent(
          new X3D.ComponentInfo(c.name, c.level, c.title, c.providerURL, false, c.dependencies));
    }
    // TimeSensors are started in the document, before X_ITE reads it: a
    // set_startTime sent to a sensor already active is ignored (X3D §8.4.1).
    const dom = new DOMParser().parseFromString(await sceneText(), "application/xml");
    const sensors = Array.from(dom.getElementsByTagName("TimeSensor"));
    for (const clock of page.clocks) {
      const sensor = sensors.find(s => s.getAttribute("DEF") === clock.timeSensor);
      if (sensor) sensor.setAttribute("startTime", String(startTime(clock)));
    }
    // ?still: no TimeSensor starts, so the page shows the scene's moment 0,
    // each baked shape's first frame, as `functionlab render` draws it.
    if (new URLSearchParams(location.search).has("still"))
      for (const sensor of sensors) {
        sensor.setAttribute("startTime", "1e15");
        sensor.setAttribute("stopTime", "0");
      }
    const scene = await browser.importDocument(dom);
    await browser.replaceWorld(scene);
    document.body.dataset.ready = "yes";
  }

  // Opened from a file, X_ITE's fetch of a wasm helper it does not need to
  // draw these meshes is refused; said once here, not as an error.
  window.addEventListener("unhandledrejection", event => {
    if (location.protocol === "file:" && String(event.reason).includes("Failed to fetch")) {
      event.preventDefault();
      console.info("X_ITE could not fetch a helper from a file; the scene does not need it");
    }
  });

  window.addEventListener("load", () => {
    if (new URLSearchParams(location.search).has("shot")) document.body.classList.add("shot");
    start().catch(error => {
      document.getElementById("status").textContent = "The scene could not be shown: " + error;
      document.body.dataset.ready = "failed";
    });
  });
})();
)js";

inline constexpr const char* kPageStyle = R"css(body {
  margin: 0;
  display: flex;
  flex-direction: column;
  height: 100vh;
  font-family: sans-serif;
  color: #222;
  background: #fafafa;
}
header, footer {
  padding: 0 1rem;
}
header p {
  margin: 0.3rem 0;
}
h1 {
  font-size: 1.3rem;
  margin: 0.6rem 0 0.2rem;
}
.limits {
  color: #555;
}
x3d-canvas {
  flex: 1 1 auto;
  width: 100%;
  min-height: 240px;
}
footer {
  font-size: 0.85rem;
  color: #666;
  padding-bottom: 0.4rem;
}
body.shot header, body.shot footer {
  display: none;
}
body.shot x3d-canvas {
  height: 100vh;
}
)css";

} // namespace fl::web
