// The report's behaviour: the animation player (a canvas redrawn from the embedded poses) and
// the zoomable plots (dygraphs, inlined from Debian's libjs-dygraphs when present).
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("report-data").textContent);
  const colours = { dynamic: "#c0504d", fixed: "#9a9a9a", driven: "#4f81bd" };
  const state = { frame: 0, playing: false, time: 0, speed: 1, last: null, box: data.animation.view };

  const canvas = document.getElementById("anim-canvas");
  const ctx = canvas.getContext("2d");
  const slider = document.getElementById("anim-slider");
  const label = document.getElementById("anim-time");
  const playButton = document.getElementById("anim-play");
  const anim = data.animation;
  slider.max = anim.t.length - 1;

  // Corners of a body at frame k: centroid + R(rot) * corner.
  function corners(body, k) {
    const [x, y, rot] = body.fixed ? [body.fixed[0], body.fixed[1], 0] : [body.x[k], body.y[k], body.rot[k]];
    const c = Math.cos(rot), s = Math.sin(rot);
    return body.corners.map(([u, v]) => [x + c * u - s * v, y + s * u + c * v]);
  }

  // Equal scale in x and y, the box centred in the canvas, y pointing up.
  function transform() {
    const [x0, x1, y0, y1] = state.box;
    const scale = Math.min(canvas.width / (x1 - x0), canvas.height / (y1 - y0));
    const ox = (canvas.width - scale * (x1 - x0)) / 2, oy = (canvas.height - scale * (y1 - y0)) / 2;
    return { scale, px: (x) => ox + (x - x0) * scale, py: (y) => canvas.height - oy - (y - y0) * scale };
  }

  function scaleBar(tr) {
    const span = (state.box[1] - state.box[0]) / 5;
    const length = Math.pow(10, Math.floor(Math.log10(span)));
    const nice = [5, 2, 1].map((m) => m * length).find((l) => l <= span) || length;
    const x = 15, y = canvas.height - 15;
    ctx.strokeStyle = "#000"; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(x + nice * tr.scale, y); ctx.stroke();
    ctx.fillStyle = "#000"; ctx.font = "13px sans-serif";
    ctx.fillText(`${nice} m`, x, y - 6);
  }

  function draw() {
    const k = state.frame;
    const tr = transform();
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    for (const body of anim.bodies) {
      const pts = corners(body, k);
      ctx.beginPath();
      pts.forEach(([x, y], i) => (i ? ctx.lineTo(tr.px(x), tr.py(y)) : ctx.moveTo(tr.px(x), tr.py(y))));
      ctx.closePath();
      ctx.fillStyle = colours[body.kind] || "#888";
      ctx.fill();
      ctx.strokeStyle = "#000"; ctx.lineWidth = 1; ctx.stroke();
    }
    scaleBar(tr);
    label.textContent = `t = ${anim.t[k].toFixed(3)} s`;
    label.dataset.frame = String(k);
    slider.value = String(k);
  }

  function seek(time) {
    state.time = time;
    let k = state.frame;
    if (anim.t[k] > time) k = 0;
    while (k + 1 < anim.t.length && anim.t[k + 1] <= time) k++;
    state.frame = k;
    draw();
  }

  // Plays in simulated time at state.speed times real time; loops at the end.
  function tick(now) {
    if (!state.playing) { state.last = null; return; }
    if (state.last !== null) {
      let time = state.time + ((now - state.last) / 1000) * state.speed;
      if (time > anim.t[anim.t.length - 1]) time = anim.t[0];
      seek(time);
    }
    state.last = now;
    requestAnimationFrame(tick);
  }

  function setPlaying(on) {
    state.playing = on;
    playButton.textContent = on ? "Pause" : "Play";
    if (on) requestAnimationFrame(tick);
  }

  playButton.addEventListener("click", () => setPlaying(!state.playing));
  slider.addEventListener("input", () => { state.frame = Number(slider.value); state.time = anim.t[state.frame]; draw(); });
  document.getElementById("anim-speed").addEventListener("change", (e) => { state.speed = Number(e.target.value); });
  document.getElementById("anim-view").addEventListener("change", (e) => {
    state.box = e.target.value === "scene" ? anim.scene : anim.view;
    draw();
  });

  // A plot click moves the animation to that time.
  function makePlots() {
    const holder = document.getElementById("plot-area");
    if (typeof Dygraph === "undefined") {
      holder.insertAdjacentHTML("beforeend",
        "<p class='note'>Interactive plots need Debian's libjs-dygraphs when the report is made; " +
        "the figures below show the same data.</p>");
      return [];
    }
    return data.plots.map((p) => {
      holder.insertAdjacentHTML("beforeend", `<h3>${p.title}</h3>`);
      const div = document.createElement("div");
      div.className = "plot";
      holder.appendChild(div);
      if (p.thinned) holder.insertAdjacentHTML("beforeend", "<p class='note'>Thinned for display; the full record is in the CSV files.</p>");
      return new Dygraph(div, p.rows, {
        labels: p.labels, xlabel: "time [s]", ylabel: p.ylabel, showRangeSelector: true,
        legend: "always", strokeWidth: 1.0, rangeSelectorHeight: 30,
        // Room for values such as -1.23e-13, written with 3 significant digits.
        axes: { y: { axisLabelWidth: 72, axisLabelFormatter: (v) => Number(v).toPrecision(3) } },
        clickCallback: (event, x) => seek(x),
      });
    });
  }

  const graphs = makePlots();
  seek(0);
  setPlaying(true);
  window.blockdemReport = { ready: true, state, graphs: graphs.length, frames: anim.t.length };
})();
