"use strict";
// Any figure full size in a viewer above the page: the wheel zooms about the pointer, a drag pans,
// 0 fits it again (it opens fitted), Escape closes. The viewer shows a copy of the figure, refreshed as time moves.

const zoom = { source: null, scale: 1, x: 0, y: 0, drag: null };

function openFigure(drawing) {
  zoom.source = drawing; zoom.scale = 1; zoom.x = 0; zoom.y = 0;
  const block = drawing.closest("details.block");
  const agent = drawing.closest(".agent");
  $("viewer-title").textContent = `${agent ? agent.dataset.agent : ""}: ${block ? block.dataset.key : ""}`;
  $("viewer").hidden = false;
  refreshFigure();
  fitFigure();
}

// The scale that shows the whole figure in the viewer, top left.
function fitFigure() {
  zoom.scale = 1; zoom.x = 0; zoom.y = 0; placeFigure();
  const figure = $("viewer-figure").getBoundingClientRect(), stage = $("viewer-stage").getBoundingClientRect();
  if (figure.width && figure.height) zoom.scale = Math.min(stage.width / figure.width, stage.height / figure.height);
  placeFigure();
}

function closeFigure() { $("viewer").hidden = true; zoom.source = null; }

function refreshFigure() {
  if (!zoom.source) return;
  if (!zoom.source.isConnected) { $("viewer-note").textContent = "this state is no longer active"; return; }
  $("viewer-note").textContent = "";
  const svg = zoom.source.querySelector("svg");
  $("viewer-figure").replaceChildren(svg ? svg.cloneNode(true) : document.createTextNode(""));
  placeFigure();
}

function placeFigure() {
  $("viewer-figure").style.transform = `translate(${zoom.x}px, ${zoom.y}px) scale(${zoom.scale})`;
  $("viewer-scale").textContent = `${Math.round(zoom.scale * 100)} %`;
}

function setUpZoom() {
  const stage = $("viewer-stage");
  stage.addEventListener("wheel", event => {
    event.preventDefault();
    const box = stage.getBoundingClientRect();
    const px = event.clientX - box.left, py = event.clientY - box.top;
    const factor = Math.exp(-event.deltaY / 400);
    const scale = Math.min(20, Math.max(0.1, zoom.scale * factor));
    zoom.x = px - (px - zoom.x) * (scale / zoom.scale);
    zoom.y = py - (py - zoom.y) * (scale / zoom.scale);
    zoom.scale = scale;
    placeFigure();
  }, { passive: false });
  stage.addEventListener("pointerdown", event => {
    zoom.drag = { x: event.clientX - zoom.x, y: event.clientY - zoom.y };
    stage.setPointerCapture(event.pointerId);
  });
  stage.addEventListener("pointermove", event => {
    if (!zoom.drag) return;
    zoom.x = event.clientX - zoom.drag.x; zoom.y = event.clientY - zoom.drag.y;
    placeFigure();
  });
  stage.addEventListener("pointerup", () => { zoom.drag = null; });
  $("viewer-close").onclick = closeFigure;
  $("viewer-fit").onclick = fitFigure;
  $("agents").addEventListener("click", event => {
    const button = event.target.closest("button.enlarge");
    if (button) openFigure(button.parentElement);
  });
}
