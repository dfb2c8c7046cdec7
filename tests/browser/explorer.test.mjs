// End-to-end test of the explorer (`arch-enum serve`) in a real browser: Debian's chromium
// driven headless by playwright-core. Run by node's test runner: `node --test tests/browser/`
// after `cargo build --release` (the binary: $ARCH_ENUM_BIN, else
// $CARGO_TARGET_DIR/release/arch-enum, else target/release/arch-enum).
//
// It loads the page, moves the mu slider with the mouse, and checks that eta* and the mode
// shown are the ones the CLI prints for the mu the page shows; that a bad input shows the
// server's message next to the input; and that no console error or page error appears.
// The screenshot goes to docs/gallery/explorer.png with UPDATE_SCREENSHOT=1, else to a
// temporary folder.

import { test } from "node:test";
import assert from "node:assert/strict";
import { spawn, execFileSync } from "node:child_process";
import { mkdtempSync, rmSync, existsSync } from "node:fs";
import { tmpdir } from "node:os";
import path from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "../..");
const BIN =
  process.env.ARCH_ENUM_BIN ||
  path.join(process.env.CARGO_TARGET_DIR || path.join(ROOT, "target"), "release", "arch-enum");
const CHROMIUM = process.env.CHROMIUM || "/usr/bin/chromium";

/** The CLI's --json document for `args` (exit 0 or 1: an answer; 2: the error document). */
function cli(args) {
  try {
    return JSON.parse(execFileSync(BIN, [...args, "--json"], { encoding: "utf8", stdio: ["ignore", "pipe", "ignore"] }));
  } catch (e) {
    if (e.status === 1 || e.status === 2) return JSON.parse(e.stdout);
    throw e;
  }
}

/** Starts `arch-enum serve --port 0`; resolves to { url, stop }. */
function startServer() {
  const child = spawn(BIN, ["serve", "--port", "0"], { stdio: ["ignore", "pipe", "ignore"] });
  return new Promise((resolve, reject) => {
    let out = "";
    const timer = setTimeout(() => reject(new Error("serve printed no URL within 10 s")), 10_000);
    child.on("error", reject);
    child.on("exit", (code) => reject(new Error(`serve exited early with ${code}`)));
    child.stdout.on("data", (d) => {
      out += d;
      const nl = out.indexOf("\n");
      if (nl >= 0) {
        clearTimeout(timer);
        resolve({ url: out.slice(0, nl).trim(), stop: () => child.kill("SIGTERM") });
      }
    });
  });
}

test("the explorer follows the mu slider with the library's eta* and mode", { timeout: 120_000 }, async () => {
  assert.ok(existsSync(BIN), `no binary at ${BIN} (cargo build --release first)`);
  assert.ok(existsSync(CHROMIUM), `no chromium at ${CHROMIUM} (apt-get install chromium)`);
  const server = await startServer();
  const profile = mkdtempSync(path.join(tmpdir(), "arch-enum-chromium-"));
  const shots = mkdtempSync(path.join(tmpdir(), "arch-enum-shot-"));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    viewport: { width: 1500, height: 940 },
    args: [
      "--headless",
      "--no-sandbox",
      "--disable-gpu",
      "--disable-quic",
      "--no-first-run",
      "--disable-background-networking",
      "--disable-component-update",
      "--disable-sync",
    ],
  });
  const errors = [];
  try {
    const page = context.pages()[0] || (await context.newPage());
    page.on("console", (m) => {
      if (m.type() === "error") errors.push(`console: ${m.text()}`);
    });
    page.on("pageerror", (e) => errors.push(`page: ${e.message}`));

    const response = await page.goto(server.url);
    assert.equal(response.status(), 200);
    assert.match(response.headers()["content-type"], /^text\/html/);

    /** Waits until the page shows the CLI's eta* and mode for the mu it displays. */
    async function expectShown(args) {
      const doc = cli(["solve", ...args]);
      assert.equal(doc.status, "ok", `the CLI answers ${args.join(" ")}`);
      await page.waitForFunction(
        ([eta, mode]) =>
          document.getElementById("eta-star").dataset.value !== "" &&
          Number(document.getElementById("eta-star").dataset.value) === eta &&
          document.getElementById("mode").dataset.value === mode,
        [doc.eta, doc.mode],
        { timeout: 15_000 },
      );
      return doc;
    }

    // the first state: alpha = 0 deg, mu as in the mu box
    const mu0 = await page.inputValue("#mu");
    const first = await expectShown(["--alpha-deg", "0", "--mu", mu0]);

    // move the slider with the mouse: low friction, then high friction
    const slider = page.locator("#mu-slider");
    const box = await slider.boundingBox();
    const seen = [first];
    // the thumb's centre runs from half a thumb (about 8 px) to the width less half a thumb
    for (const fraction of [0.3295, 0.85]) {
      await page.mouse.click(box.x + 8 + fraction * (box.width - 16), box.y + box.height / 2);
      const mu = await page.inputValue("#mu");
      assert.notEqual(mu, mu0, "the slider moved mu");
      seen.push(await expectShown(["--alpha-deg", "0", "--mu", mu]));
    }
    // the two slider positions show different limit states (a different eta* and mode)
    assert.notEqual(seen[1].eta, seen[2].eta);
    assert.notEqual(seen[1].mode, seen[2].mode);

    // mu = infinity: Couplet-Heyman
    await page.check("#mu-inf");
    await expectShown(["--alpha-deg", "0", "--mu", "inf"]);
    await page.uncheck("#mu-inf");
    await page.fill("#mu", "0.35");
    await expectShown(["--alpha-deg", "0", "--mu", "0.35"]);

    // the diagram, the arch figure and the numbers are on the page
    await page.waitForSelector("#diagram svg .curve");
    await page.waitForSelector("#diagram svg .corner");
    await page.waitForSelector("#figure svg");
    await page.waitForFunction(() => document.getElementById("geometric-factor").textContent !== "–");
    const shot = process.env.UPDATE_SCREENSHOT === "1"
      ? path.join(ROOT, "docs", "gallery", "explorer.png")
      : path.join(shots, "explorer.png");
    await page.screenshot({ path: shot, fullPage: false });
    assert.deepEqual(errors, [], "no console error or page error");

    // "enlarge": the figure spans the diagram's column too, its text at least 1.8 times as
    // large on the screen; pressed again it goes back beside the diagram
    const figureWidth = () => page.evaluate(() => document.querySelector("#figure svg").getBoundingClientRect().width);
    const narrow = await figureWidth();
    await page.click("#enlarge");
    const wide = await figureWidth();
    assert.ok(wide >= 1.8 * narrow, `enlarged ${wide} px from ${narrow} px`);
    assert.equal(await page.getAttribute("#enlarge", "aria-pressed"), "true");
    await page.click("#enlarge");
    assert.ok(Math.abs((await figureWidth()) - narrow) < 1, "back beside the diagram");

    // in metres: a 10 m semicircle with a 0.6 m ring is the arch alpha = 0 (the same eta*),
    // and the page shows what the ring gives (eta = 0.6/5.3) and the least ring
    await page.check('input[name="shape"][value="metres"]');
    await page.fill("#span", "10");
    await page.fill("#rise", "5");
    await page.fill("#ring", "0.6");
    await expectShown(["--span", "10", "--rise", "5", "--mu", "0.35"]);
    const assessed = cli(["assess", "--span", "10", "--rise", "5", "--ring", "0.6", "--mu", "0.35"]);
    await page.waitForFunction(
      (eta) => document.getElementById("geometry").textContent.includes(`η = t/r = ${Number(eta).toPrecision(6)}`)
        && document.getElementById("geometry").textContent.includes("least ring t*"),
      assessed.geometry.eta,
      { timeout: 15_000 },
    );
    assert.deepEqual(errors, [], "no console error or page error in metres");

    // their arch: the figure shown first is the arch at the ring given (eta = 0.6/5.3), not
    // the thinner limit state (at mu = 0.6, where it stands)
    await page.click('.tab[data-fig="mine"]');
    await page.fill("#mu", "0.6");
    await page.waitForFunction(
      (eta) => (document.querySelector("#figure svg text") || {}).textContent?.includes(`η = ${eta}`),
      Number(assessed.geometry.eta).toFixed(3),
      { timeout: 15_000 },
    );

    // one colour table: the page's colour of the limit state's mode is the figure's
    const mode = cli(["solve", "--span", "10", "--rise", "5", "--mu", "0.35"]).mode;
    const colour = await page.evaluate((m) => MODE_COLOURS[m], mode);
    const figure = await (await page.request.get(`${server.url}api/plot/arch?span=10&rise=5&mu=0.35`)).text();
    assert.ok(colour && figure.toLowerCase().includes(colour.toLowerCase()), `${mode}: ${colour} in the figure`);

    // fill and a vehicle at its critical position: the adequacy factor and X* are the CLI's
    await page.check("#fill");
    await page.fill("#fill-weight", "18");
    await page.fill("#fill-depth", "0.3");
    await page.selectOption("#load", "vehicle");
    await page.fill("#axles", "100");
    const bridge = ["--span", "10", "--rise", "5", "--ring", "0.6", "--unit-weight", "20", "--width", "1",
      "--mu", "0.6", "--fill-weight", "18", "--fill-depth", "0.3", "--axles", "100", "--critical", "--samples", "21"];
    const vehicle = cli(["load", ...bridge]);
    assert.equal(vehicle.status, "ok");
    await page.waitForFunction(
      ([l, at]) => document.getElementById("adequacy").textContent.startsWith(l)
        && document.getElementById("critical-at").textContent.startsWith(at),
      [Number(vehicle.lambda).toPrecision(4), Number(vehicle.critical.at_m).toPrecision(5)],
      { timeout: 60_000 },
    );
    await page.waitForSelector('#figure svg', { timeout: 60_000 });
    assert.match(await page.getAttribute("#dl-report", "href"), /^\/api\/report\?.*axles=100/);
    // with fill the diagram is curve's sampled eta*(mu) of the arch with its fill (the
    // diagram without fill is on the page until that curve arrives: wait for its legend)
    await page.waitForFunction(
      () => /with fill: η\*\(μ\) sampled/.test(document.getElementById("legend").textContent),
      null,
      { timeout: 60_000 },
    );
    await page.waitForSelector("#diagram svg .curve", { timeout: 60_000 });
    assert.match(await page.textContent("#legend"), /with fill: η\*\(μ\) sampled/);
    assert.deepEqual(errors, [], "no console error or page error with fill and a vehicle");

    // usable at 1024 px and on a phone (420 px): nothing wider than the screen
    for (const width of [1024, 420]) {
      await page.setViewportSize({ width, height: 900 });
      const scroll = await page.evaluate(() => document.documentElement.scrollWidth);
      assert.ok(scroll <= width, `nothing wider than ${width} px (${scroll} px)`);
      const wide = process.env.UPDATE_SCREENSHOT === "1"
        ? path.join(ROOT, "docs", "gallery", `explorer_${width}.png`)
        : path.join(shots, `explorer_${width}.png`);
      await page.screenshot({ path: wide, fullPage: width === 420 });
    }
    await page.setViewportSize({ width: 1500, height: 940 });
    await page.selectOption("#load", "none");
    await page.uncheck("#fill");
    await page.check('input[name="shape"][value="alpha"]');

    // bad input: the server's 400 message next to the input (the browser logs the failed
    // requests themselves as console errors: those, and only those, are expected here)
    await page.fill("#alpha-deg", "95");
    const alphaErr = page.locator('.err[data-for="alpha-deg"]');
    await alphaErr.filter({ hasText: "--alpha-deg" }).waitFor({ timeout: 15_000 });
    const message = await alphaErr.textContent();
    const expected = cli(["solve", "--alpha-deg", "95", "--mu", "0.35"]);
    assert.equal(expected.status, "error");
    assert.ok(message.includes(expected.message), `shown: ${message}; CLI: ${expected.message}`);
    const unexpected = errors.filter((e) => !/status of 400/.test(e));
    assert.deepEqual(unexpected, [], "only the refused requests are logged");
  } finally {
    await context.close();
    server.stop();
    rmSync(profile, { recursive: true, force: true });
    rmSync(shots, { recursive: true, force: true });
  }
});
