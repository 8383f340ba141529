// The 3-D report's zoomable plots (dygraphs, inlined from Debian's libjs-dygraphs when present).
// No animation player: the bodies are drawn in the figures from the VTK frames.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("report-data").textContent);
  const holder = document.getElementById("plot-area");
  let graphs = [];
  if (typeof Dygraph === "undefined") {
    holder.insertAdjacentHTML("beforeend",
      "<p class='note'>Interactive plots need Debian's libjs-dygraphs when the report is made; " +
      "the figures above show the same data.</p>");
  } else {
    graphs = data.plots.map((p) => {
      const heading = document.createElement("h3");
      heading.textContent = p.title;
      holder.appendChild(heading);
      const div = document.createElement("div");
      div.className = "plot";
      holder.appendChild(div);
      if (p.thinned) holder.insertAdjacentHTML("beforeend", "<p class='note'>Thinned for display; the full record is in the CSV files.</p>");
      return new Dygraph(div, p.rows, {
        labels: p.labels, xlabel: "time [s]", ylabel: p.ylabel, showRangeSelector: true,
        legend: "always", strokeWidth: 1.0, rangeSelectorHeight: 30,
        axes: { y: { axisLabelWidth: 72, axisLabelFormatter: (v) => Number(v).toPrecision(3) } },
      });
    });
  }
  window.blockdemReport = { ready: true, graphs: graphs.length };
  document.body.dataset.plotsDrawn = String(graphs.length);  // read back by tests/cli/test_report_3d.sh
})();
