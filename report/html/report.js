// The report's image comparisons (figure.compare, written by tools/make-report): two images of
// the same size stacked, the upper one clipped at a split the reader drags ("slider"), or one of
// them alone ("a", "b": a click on the image flips between them), at zoom 1 to 16 with the
// nearest pixel, so that single pixels can be compared. The false-colour map beside each pair
// is computed by tools/make-report: a page opened from disk may not read its own images' pixels.
"use strict";

function setUpComparison(figure) {
  const frame = figure.querySelector(".compare-frame");
  const view = figure.querySelector(".compare-view");
  const upper = figure.querySelector(".compare-b");
  const handle = figure.querySelector(".compare-handle");
  const width = Number(view.dataset.width);
  const height = Number(view.dataset.height);
  const state = { mode: "slider", split: 0.5, zoom: 1, dragging: false };

  function show() {
    const percent = `${(100 * state.split).toFixed(4)}%`;
    upper.hidden = state.mode === "a";
    upper.style.clipPath = state.mode === "slider" ? `inset(0 0 0 ${percent})` : "none";
    handle.hidden = state.mode !== "slider";
    handle.style.left = percent;
    view.style.width = `${width * state.zoom}px`;
    view.style.height = `${height * state.zoom}px`;
    for (const button of figure.querySelectorAll(".compare-mode")) {
      button.setAttribute("aria-pressed", String(button.dataset.mode === state.mode));
    }
    for (const button of figure.querySelectorAll(".compare-zoom")) {
      button.setAttribute("aria-pressed", String(Number(button.dataset.zoom) === state.zoom));
    }
  }

  function splitAt(event) {
    const box = view.getBoundingClientRect();
    state.split = Math.min(1, Math.max(0, (event.clientX - box.left) / box.width));
    show();
  }

  // Zooming keeps the point at the frame's centre where it was.
  function zoomTo(zoom) {
    const centreX = (frame.scrollLeft + frame.clientWidth / 2) / state.zoom;
    const centreY = (frame.scrollTop + frame.clientHeight / 2) / state.zoom;
    state.zoom = zoom;
    show();
    frame.scrollLeft = centreX * zoom - frame.clientWidth / 2;
    frame.scrollTop = centreY * zoom - frame.clientHeight / 2;
  }

  for (const button of figure.querySelectorAll(".compare-mode")) {
    button.addEventListener("click", () => { state.mode = button.dataset.mode; show(); });
  }
  for (const button of figure.querySelectorAll(".compare-zoom")) {
    button.addEventListener("click", () => zoomTo(Number(button.dataset.zoom)));
  }
  view.addEventListener("pointerdown", (event) => {
    if (event.button !== 0) return;
    event.preventDefault();  // no image drag-and-drop, no text selection
    if (state.mode === "slider") {
      state.dragging = true;
      view.setPointerCapture(event.pointerId);
      splitAt(event);
    } else {
      state.mode = state.mode === "a" ? "b" : "a";
      show();
    }
  });
  view.addEventListener("pointermove", (event) => { if (state.dragging) splitAt(event); });
  view.addEventListener("pointerup", () => { state.dragging = false; });
  view.addEventListener("pointercancel", () => { state.dragging = false; });
  view.addEventListener("keydown", (event) => {
    const steps = { ArrowLeft: -1, ArrowRight: 1 };
    if (event.key in steps && state.mode === "slider") {
      state.split = Math.min(1, Math.max(0, state.split + steps[event.key] / width));
    } else if (event.key === " " || event.key === "f") {
      state.mode = state.mode === "a" ? "b" : "a";
    } else {
      return;
    }
    event.preventDefault();
    show();
  });
  show();
}

document.querySelectorAll("figure.compare").forEach(setUpComparison);
