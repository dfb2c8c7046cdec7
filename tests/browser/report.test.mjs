// The assessment report (`arch-enum report`) in a real browser: Debian's chromium driven
// headless by playwright-core. Run by node's test runner: `node --test tests/browser/` after
// `cargo build --release`.
//
// It writes the README's bridge report, opens it from the file system (no server, no
// network), and checks at 1500, 1024 and 420 px wide that it renders without a console or
// page error, that nothing is wider than the page, that its numbers are the CLI's `--json`
// (λ, X*, η/η*), that the certificate is verified, and that it prints to a PDF. With
// UPDATE_SCREENSHOT=1 the screenshots and the PDF go to docs/gallery/, else to a temporary
// folder.

import { test } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdtempSync, rmSync, existsSync, statSync } from "node:fs";
import { tmpdir } from "node:os";
import path from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";
import { chromium } from "playwright-core";

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "../..");
const BIN =
  process.env.ARCH_ENUM_BIN ||
  path.join(process.env.CARGO_TARGET_DIR || path.join(ROOT, "target"), "release", "arch-enum");
const CHROMIUM = process.env.CHROMIUM || "/usr/bin/chromium";

const BRIDGE = [
  "--span", "10", "--rise", "5", "--ring", "0.6", "--width", "1", "--unit-weight", "20",
  "--mu", "0.6", "--fill-weight", "18", "--fill-depth", "0.3", "--axles", "100", "--samples", "21",
];

/** `v` to `digits` significant digits as the report prints it (fixed point here). */
function sig(v, digits) {
  const e = Math.floor(Math.log10(Math.abs(v)));
  return v.toFixed(Math.max(0, digits - 1 - e));
}

test("the bridge report renders, prints, and shows the CLI's numbers", { timeout: 180_000 }, async () => {
  assert.ok(existsSync(BIN), `no binary at ${BIN} (cargo build --release first)`);
  assert.ok(existsSync(CHROMIUM), `no chromium at ${CHROMIUM} (apt-get install chromium)`);
  const work = mkdtempSync(path.join(tmpdir(), "arch-enum-report-"));
  const out = process.env.UPDATE_SCREENSHOT === "1" ? path.join(ROOT, "docs", "gallery") : work;
  const report = path.join(work, "bridge.html");
  execFileSync(BIN, ["report", "--out", report, ...BRIDGE], { stdio: "ignore" });
  const load = JSON.parse(execFileSync(BIN, ["load", ...BRIDGE, "--critical", "--json"], { encoding: "utf8" }));
  const assess = JSON.parse(execFileSync(BIN, ["assess", ...BRIDGE.slice(0, 16), "--json"], { encoding: "utf8" }));

  const profile = mkdtempSync(path.join(tmpdir(), "arch-enum-chromium-"));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    args: ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking"],
  });
  const errors = [];
  const requests = [];
  try {
    const page = context.pages()[0] || (await context.newPage());
    page.on("console", (m) => {
      if (m.type() === "error") errors.push(`console: ${m.text()}`);
    });
    page.on("pageerror", (e) => errors.push(`page: ${e.message}`));
    page.on("request", (r) => {
      if (!r.url().startsWith("file:") && !r.url().startsWith("data:")) requests.push(r.url());
    });
    for (const width of [1500, 1024, 420]) {
      await page.setViewportSize({ width, height: 900 });
      await page.goto(pathToFileURL(report).href);
      const text = await page.innerText("body");
      assert.ok(text.includes(sig(load.lambda, 10)), `λ = ${sig(load.lambda, 10)} shown`);
      assert.ok(text.includes(sig(load.critical.at_m, 8)), `X* = ${sig(load.critical.at_m, 8)} shown`);
      assert.ok(text.includes(sig(assess.geometric_factor, 6)), "η/η* shown");
      assert.ok(text.includes(sig(assess.mu_min, 12)), "μ_min shown");
      assert.match(text, /Certificate verified by arch-enum verify/);
      assert.equal(await page.locator("figure").count(), 2, "the arch and the influence line");
      const scroll = await page.evaluate(() => document.documentElement.scrollWidth);
      assert.ok(scroll <= width, `nothing wider than the page at ${width} px (${scroll} px)`);
      await page.screenshot({ path: path.join(out, `report_${width}.png`), fullPage: width !== 1500 ? false : true });
    }
    const pdf = path.join(out, "report.pdf");
    await page.emulateMedia({ media: "print" });
    await page.pdf({ path: pdf, format: "A4", printBackground: true });
    assert.ok(statSync(pdf).size > 20_000, "a PDF with the figures");
    assert.deepEqual(errors, [], "no console error or page error");
    assert.deepEqual(requests, [], "no network request");
  } finally {
    await context.close();
    rmSync(profile, { recursive: true, force: true });
    rmSync(work, { recursive: true, force: true });
  }
});
