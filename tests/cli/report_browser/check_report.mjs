// Opens a report.html in Debian's headless Chromium (driven by playwright-core, no browser
// download) and checks what a person would see: the page loads with no console errors, the
// animation advances by itself, the canvas shows the blocks, and the zoomable plots are drawn.
// Usage: node check_report.mjs REPORT_HTML SCREENSHOT_DIR [MIN_PLOTS]
import { chromium } from "playwright-core";
import { mkdtempSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { pathToFileURL } from "node:url";

const [report, shots, minPlots = "1"] = process.argv.slice(2);
const failures = [];
const check = (ok, what) => { console.log(`${ok ? "ok  " : "FAIL"} ${what}`); if (!ok) failures.push(what); };

// A fresh profile each time (playwright passes it as --user-data-dir).
const browser = await chromium.launchPersistentContext(mkdtempSync(join(tmpdir(), "bd-chromium-")), {
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  viewport: { width: 1200, height: 900 },
  args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
         "--disable-component-update", "--disable-sync"],
});
try {
  const page = await browser.newPage();
  const errors = [];
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  page.on("pageerror", (e) => errors.push(String(e)));
  const requests = [];
  page.on("request", (r) => { if (!r.url().startsWith("file:") && !r.url().startsWith("data:")) requests.push(r.url()); });

  await page.goto(pathToFileURL(resolve(report)).href, { waitUntil: "load" });
  await page.waitForFunction(() => window.blockdemReport && window.blockdemReport.ready, null, { timeout: 10000 });
  const frame = () => page.$eval("#anim-time", (e) => Number(e.dataset.frame));
  // Sampled over 1.5 s: a short run loops, so count the samples where the frame moved on rather
  // than the distinct frames (on a loaded machine a sample can fall every third frame of a
  // 12-frame loop and see only 4 of them while the animation runs).
  const seen = [];
  for (let i = 0; i < 15; i++) { seen.push(await frame()); await page.waitForTimeout(100); }
  const moves = seen.filter((f, i) => i > 0 && f !== seen[i - 1]).length;
  check(moves >= 5 && new Set(seen).size >= 2,
        `the animation advances by itself (${moves} moves in 1.5 s: ${seen.join(" ")})`);

  // Pixels of the dynamic-body colour (#c0504d) on the canvas: the blocks are drawn.
  const blockPixels = await page.$eval("#anim-canvas", (c) => {
    const d = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] === 0xc0 && d[i + 1] === 0x50 && d[i + 2] === 0x4d) n++;
    return n;
  });
  check(blockPixels > 500, `the canvas shows the blocks (${blockPixels} block-coloured pixels)`);
  const plots = await page.evaluate(() => window.blockdemReport.graphs);
  const drawn = await page.$$eval("#plot-area .plot canvas", (c) => c.length);
  check(plots >= Number(minPlots) && drawn >= plots, `${plots} zoomable plots drawn (${drawn} canvases)`);
  check((await page.$$eval("figure img", (i) => i.filter((x) => x.naturalWidth > 0).length)) >= 3, "the figures are shown");
  await page.locator("#anim-canvas").screenshot({ path: join(shots, "report_animation.png") });
  await page.screenshot({ path: join(shots, "report_page.png"), fullPage: false });
  check(requests.length === 0, `no network requests (${requests.join(", ")})`);
  check(errors.length === 0, `no console errors${errors.length ? ": " + errors.join(" | ") : ""}`);
} finally {
  await browser.close();
}
if (failures.length) { console.log(`${failures.length} check(s) failed`); process.exit(1); }
console.log("report checks passed");
