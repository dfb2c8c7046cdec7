// arch-enum explorer: reads the inputs, asks the local API (the CLI's --json documents and
// the library's SVG figures), draws the eta-mu diagram in SVG, shows the numbers.
// No library, no build step.
"use strict";

const $ = (id) => document.getElementById(id);
const SVG_NS = "http://www.w3.org/2000/svg";

// mu slider: log scale over [MU_LO, MU_HI], 1000 steps; the value sent is rounded to 4
// significant digits (the number shown is the number asked).
const MU_LO = 0.05, MU_HI = 20;
const muOfSlider = (s) =>
  Number(Math.pow(10, Math.log10(MU_LO) + (s / 1000) * Math.log10(MU_HI / MU_LO)).toPrecision(4));
const sliderOfMu = (mu) =>
  Math.round((1000 * Math.log10(mu / MU_LO)) / Math.log10(MU_HI / MU_LO));

// the figures' own mode colours (src/render/plot.rs), written in by the server
const MODE_COLOURS = /*MODE_COLOURS*/{};
const modeColour = (m) => MODE_COLOURS[m] || "#7f7f7f";
const KIND = {
  hinge_extrados: "E",
  hinge_intrados: "I",
  slide_plus: "S+",
  slide_minus: "S−",
};

const fmt = (x, p = 6) => (x === null || x === undefined ? "–" : Number(x).toPrecision(p));

// ---------------------------------------------------------------- inputs -> parameters
function archParams() {
  const p = {};
  const shape = document.querySelector('input[name="shape"]:checked').value;
  if (shape === "alpha") {
    p["alpha-deg"] = $("alpha-deg").value.trim();
  } else if (shape === "metres") {
    p.span = $("span").value.trim();
    p.rise = $("rise").value.trim();
  } else {
    p["beta-right"] = $("beta-right").value.trim();
    p["beta-left"] = $("beta-left").value.trim();
  }
  if (document.querySelector('input[name="joints"]:checked').value === "blocks") {
    p.blocks = $("blocks").value.trim();
  }
  p.weight = $("weight").value;
  return p;
}
const muValue = () => ($("mu-inf").checked ? "inf" : $("mu").value.trim());
const inMetres = () => document.querySelector('input[name="shape"]:checked').value === "metres";
// the thickness: eta, or in metres the ring (the server derives eta = t/r from it)
const thickness = () => (inMetres() ? { ring: $("ring").value.trim() } : { eta: $("eta").value.trim() });
// in metres: the masonry's unit weight and the barrel width (forces in kN)
const dims = () => (inMetres() ? { "unit-weight": $("unit-weight").value.trim(), width: $("width").value.trim() } : {});
// the fill: in metres its unit weight and the road's depth above the crown (with the
// masonry's unit weight), else the ratios g_f and h
function fillParams() {
  if (!$("fill").checked) return {};
  if (inMetres()) {
    return { "fill-weight": $("fill-weight").value.trim(), "fill-depth": $("fill-depth").value.trim(), "unit-weight": $("unit-weight").value.trim() };
  }
  return { "fill-ratio": $("fill-ratio").value.trim(), "fill-height": $("fill-height").value.trim() };
}
const hasFill = () => $("fill").checked;
function loadParams() {
  const kind = $("load").value;
  if (kind === "none") return null;
  if (kind === "point-load-deg") return { "point-load-deg": $("point-load-deg").value.trim() };
  if (kind === "vehicle") {
    const p = { axles: $("axles").value.trim() };
    if (p.axles.includes(",")) p.spacing = $("spacing").value.trim();
    // 21 samples of the influence line (the README's), each minimum then located exactly
    if ($("critical").checked) Object.assign(p, { critical: "", samples: "21" });
    else p.at = $("at").value.trim();
    return p;
  }
  return { [kind]: "" };
}
const isVehicle = () => $("load").value === "vehicle";
function query(params) {
  return Object.entries(params)
    .map(([k, v]) => (v === "" ? encodeURIComponent(k) : `${encodeURIComponent(k)}=${encodeURIComponent(v)}`))
    .join("&");
}
const url = (endpoint, params) => `/api/${endpoint}?${query(params)}`;

// ---------------------------------------------------------------- errors next to inputs
const ERROR_TARGET = {
  "alpha-deg": "alpha-deg", alpha: "alpha-deg", "beta-right": "beta-right", "beta-left": "beta-right",
  blocks: "blocks", joints: "blocks", mu: "mu", eta: "eta", "point-load-deg": "point-load-deg",
  span: "span", rise: "span", ring: "ring", "unit-weight": "unit-weight", width: "unit-weight",
  "fill-weight": "fill", "fill-depth": "fill", "fill-ratio": "fill", "fill-height": "fill",
  axles: "axles", spacing: "axles", at: "axles", patch: "axles",
};
function clearErrors() {
  document.querySelectorAll(".err").forEach((e) => (e.textContent = ""));
}
function showError(message) {
  const m = /--([a-z-]+)/.exec(message);
  const target = m && ERROR_TARGET[m[1]];
  const box = target ? document.querySelector(`.err[data-for="${target}"]`) : $("general-error");
  if (!box.textContent.includes(message)) box.textContent += (box.textContent ? " " : "") + message;
}

// ---------------------------------------------------------------- fetching
let pending = 0;
function busy(delta) {
  pending += delta;
  $("busy").hidden = pending === 0;
}
class BadInput extends Error {}
// Every API request is a computation on the server, which runs 4 at a time and refuses
// (503) one that waits more than 1.5 s for its turn (src/cli/serve/jobs.rs). The page keeps
// at most IN_FLIGHT of its own on the server, so that it alone never meets that refusal: a
// request superseded by an edit is aborted, and its computation killed within ~20 ms.
const IN_FLIGHT = 3;
let inFlight = 0;
const waiting = new Set();
async function turn(signal) {
  signal.throwIfAborted(); // superseded before its turn was asked for
  while (inFlight >= IN_FLIGHT) {
    await new Promise((wake) => {
      const done = () => {
        signal.removeEventListener("abort", done);
        waiting.delete(done);
        wake();
      };
      waiting.add(done);
      signal.addEventListener("abort", done);
    });
    signal.throwIfAborted();
  }
  inFlight += 1;
}
function turnDone() {
  inFlight -= 1;
  const all = [...waiting];
  waiting.clear();
  all.forEach((wake) => wake());
}
// The API's response to `u`, one of IN_FLIGHT at most.
async function request(u, signal) {
  await turn(signal);
  try {
    const r = await fetch(u, { signal });
    // the body too, before the turn is given back
    return { status: r.status, text: await r.text() };
  } finally {
    turnDone();
  }
}
// A document from the API: 200 -> the JSON (an answer, possibly "no equilibrium"),
// 400/422 -> BadInput with the server's message.
async function getJson(u, signal) {
  busy(1);
  try {
    const r = await request(u, signal);
    const doc = JSON.parse(r.text);
    if (r.status !== 200) throw new BadInput(doc.message || `HTTP ${r.status}`);
    return doc;
  } finally {
    busy(-1);
  }
}
async function getText(u, signal) {
  busy(1);
  try {
    const r = await request(u, signal);
    if (r.status !== 200) throw new BadInput(JSON.parse(r.text).message || `HTTP ${r.status}`);
    return r.text;
  } finally {
    busy(-1);
  }
}

// ---------------------------------------------------------------- state
const state = { modes: null, curve: null, solve: null, assess: null, load: null, fig: "mine" };
let curveCtl = null, stateCtl = null;

function debounce(fn, ms) {
  let t = null;
  return () => {
    clearTimeout(t);
    t = setTimeout(fn, ms);
  };
}

async function refreshCurve() {
  if (curveCtl) curveCtl.abort();
  const ctl = (curveCtl = new AbortController());
  const arch = archParams();
  if (hasFill()) {
    // with fill mu_ms depends on eta and modes refuses it: eta*(mu) sampled by curve (the
    // ring fixes r, and so the fill's depth ratio, in metres), without exact corners
    try {
      const withFill = { ...arch, ...fillParams(), ...(inMetres() ? thickness() : {}) };
      const range = { "mu-min": String(MU_LO), "mu-max": String(MU_HI), points: "100" };
      const curve = await getJson(url("curve", { ...withFill, ...range }), ctl.signal);
      if (ctl.signal.aborted) return;
      state.modes = { mu_ms: null, corners: [], branches: [], sampled: true };
      state.curve = curve;
      $("mu-ms").textContent = "– (with fill a curve μ_ms(η))";
    } catch (e) {
      if (e.name === "AbortError") return;
      state.modes = state.curve = null;
      if (e instanceof BadInput) showError(e.message);
      else showError(String(e));
    }
    drawDiagram();
    return;
  }
  try {
    const modes = await getJson(url("modes", arch), ctl.signal);
    const corners = modes.corners.map((c) => c.mu);
    const lo = modes.mu_ms ? modes.mu_ms * (1 + 1e-6) : MU_LO;
    const hi = Math.max(MU_HI, 3 * Math.max(lo, ...corners));
    const curve = await getJson(
      url("curve", { ...arch, "mu-min": String(lo), "mu-max": String(hi), points: "100" }),
      ctl.signal,
    );
    if (ctl.signal.aborted) return;
    state.modes = modes;
    state.curve = curve;
    $("mu-ms").textContent = fmt(modes.mu_ms);
    $("dl-modes").href = url("modes", arch);
  } catch (e) {
    if (e.name === "AbortError") return;
    state.modes = state.curve = null;
    if (e instanceof BadInput) showError(e.message);
    else showError(String(e));
  }
  drawDiagram();
}

async function refreshState() {
  if (stateCtl) stateCtl.abort();
  const ctl = (stateCtl = new AbortController());
  const arch = archParams();
  const mu = muValue();
  const eta = thickness();
  const load = loadParams();
  const fill = fillParams();
  // with fill in metres the ring fixes r, and so the fill's depth ratio, for solve too
  const solveUrl = url("solve", { ...arch, mu, ...(hasFill() && inMetres() ? eta : {}), ...fill });
  const atEta = { ...arch, ...eta, mu, ...fill, ...dims() };
  $("dl-solve").href = solveUrl;
  $("dl-cert").href = load ? url("certify", { ...atEta, ...load }) : url("certify", { ...arch, mu });
  $("dl-report").href = url("report", { ...atEta, ...(load || {}) });
  $("dl-arch").href = url("plot/arch", { ...arch, ...eta, mu, ...fill });
  $("dl-ecc").href = url("plot/eccentricity", { ...arch, mu });
  document.querySelectorAll(".loadrow").forEach((r) => (r.hidden = !load));
  document.querySelectorAll(".vehiclerow").forEach((r) => (r.hidden = !(load && isVehicle())));
  const loadFigure = load && !isVehicle() && !hasFill();
  $("dl-load").hidden = !loadFigure;
  document.querySelector('.tab[data-fig="load"]').hidden = !loadFigure;
  document.querySelector('.tab[data-fig="influence"]').hidden = !(load && isVehicle());
  if (state.fig === "load" && !loadFigure) selectFigure("mine");
  if (state.fig === "influence" && !(load && isVehicle())) selectFigure("mine");
  const assessed = getJson(url("assess", { ...arch, ...eta, mu, ...fill, ...dims() }), ctl.signal).then((d) => (state.assess = d));
  const jobs = [
    getJson(solveUrl, ctl.signal).then((d) => (state.solve = d)),
    assessed,
    load
      ? getJson(url("load", { ...atEta, ...load }), ctl.signal).then((d) => (state.load = d))
      : Promise.resolve((state.load = null)),
    refreshFigure(ctl, { arch, mu, eta, load, fill, atEta, assessed }),
  ];
  if (loadFigure) $("dl-load").href = url("plot/load", { ...arch, ...eta, mu, ...load });
  const results = await Promise.allSettled(jobs);
  if (ctl.signal.aborted) return;
  for (const r of results) {
    if (r.status === "rejected" && r.reason.name !== "AbortError") showError(r.reason.message);
  }
  if (results[0].status === "rejected") state.solve = null;
  if (results[1].status === "rejected") state.assess = null;
  if (results[2].status === "rejected") state.load = null;
  showNumbers();
  drawDiagram();
}

// The figure of the tab shown: the user's arch at eta (its safest line of thrust), the limit
// state at eta*(mu), the live load at eta, or a vehicle's influence line.
async function figureUrl({ arch, mu, eta, load, fill, atEta, assessed }) {
  if (state.fig === "load" && load) return url("plot/load", { ...arch, ...eta, mu, ...load });
  if (state.fig === "influence" && load) return url("plot/influence", { ...atEta, ...load });
  if (state.fig === "mine") {
    // an arch that does not stand has no state to draw: say so instead
    const a = await assessed.catch(() => null);
    if (a && a.stands === false) {
      throw new BadInput(`The arch does not stand at η = ${fmt(a.eta, 5)} and μ = ${mu}: no admissible state (the least thickness at this μ is η* = ${fmt(a.eta_min, 5)}).`);
    }
    return url("plot/arch", { ...arch, ...eta, mu, ...fill });
  }
  if (hasFill() && inMetres()) {
    // the limit state keeps the fill's ratios at the ring given (from assess)
    const a = await assessed;
    const f = a && a.fill ? { "fill-ratio": String(a.fill.weight_ratio), "fill-height": String(a.fill.depth_ratio) } : {};
    return url("plot/arch", { ...arch, mu, ...f });
  }
  return url("plot/arch", { ...arch, mu, ...fill });
}

async function refreshFigure(ctl, inputs) {
  const fig = $("figure");
  try {
    const u = await figureUrl(inputs);
    const svg = await getText(u, ctl.signal);
    if (ctl.signal.aborted) return;
    fig.innerHTML = svg; // the library's own figure, from this server
    const s = fig.querySelector("svg");
    if (s) {
      s.removeAttribute("width");
      s.removeAttribute("height");
    }
  } catch (e) {
    if (e.name === "AbortError") return;
    fig.innerHTML = "";
    const p = document.createElement("p");
    p.className = "nofig";
    p.textContent = e.message;
    fig.appendChild(p);
  }
}

function selectFigure(name) {
  state.fig = name;
  document.querySelectorAll(".tab").forEach((t) => t.classList.toggle("active", t.dataset.fig === name));
}

// ---------------------------------------------------------------- numbers
function patternText(pattern) {
  return pattern.map((j) => `${KIND[j.kind] || j.kind} ${((j.beta * 180) / Math.PI).toFixed(2)}°`).join(", ");
}
function showNumbers() {
  const s = state.solve, a = state.assess, l = state.load;
  const msg = [];
  $("eta-star").textContent = s && s.eta !== undefined ? fmt(s.eta) : "–";
  $("eta-star").dataset.value = s && s.eta !== undefined ? String(s.eta) : "";
  $("mode").textContent = s && s.mode ? s.mode.replaceAll("_", " ") : "–";
  $("mode").dataset.value = s && s.mode ? s.mode : "";
  $("mode").style.color = s && s.mode ? modeColour(s.mode) : "";
  $("pattern").textContent = s && s.pattern ? patternText(s.pattern) : "–";
  $("unique").textContent = s && s.unique !== undefined ? (s.unique ? "yes" : "no (see the figure's panels)") : "–";
  if (s && s.status !== "ok") msg.push(`solve: ${s.status.replaceAll("_", " ")}${s.message ? " — " + s.message : ""}`);
  if (a) {
    $("stands").textContent = a.stands ? "stands" : "does not stand";
    $("stands").className = a.stands ? "ok" : "bad";
    $("geometric-factor").textContent = fmt(a.geometric_factor, 4);
    $("friction-factor").textContent = fmt(a.friction_factor, 4);
    $("mu-min").textContent = fmt(a.mu_min);
    if (a.message) msg.push(`assess: ${a.message}`);
  } else {
    ["stands", "geometric-factor", "friction-factor", "mu-min"].forEach((id) => ($(id).textContent = "–"));
  }
  if (l) {
    $("lambda").textContent = fmt(l.lambda);
    $("lambda-static").textContent = fmt(l.lambda_static);
    const first = l.limit_states && l.limit_states[0];
    $("load-mode").textContent = first ? `${first.mode.replaceAll("_", " ")}: ${patternText(first.pattern)}` : "–";
    const kn = l.units && l.units.lambda_kn;
    $("adequacy").textContent = l.lambda === undefined || l.lambda === null ? "–" : `${fmt(l.lambda, 4)}${kn ? ` (${fmt(kn, 4)} kN)` : ""}`;
    const at = l.critical ? l.critical.at_m : l.vehicle ? l.vehicle.at_m : null;
    $("critical-at").textContent = at === null || at === undefined ? "–" : `${fmt(at, 5)} m`;
    if (l.status !== "ok") msg.push(`load: ${l.status.replaceAll("_", " ")}${l.message ? " — " + l.message : ""}`);
  }
  // in metres: what the span, rise and ring give (the documents' `geometry`)
  const g = (a && a.geometry) || (s && s.geometry);
  $("geometry").hidden = !g;
  if (g) {
    const parts = [`R_i = ${fmt(g.intrados_radius_m, 5)} m, α = ${fmt((g.alpha * 180) / Math.PI, 5)}°`];
    if (g.eta !== null && g.eta !== undefined) parts.push(`r = ${fmt(g.radius_m, 5)} m, η = t/r = ${fmt(g.eta)}`);
    const least = s && s.geometry ? s.geometry.least_ring_m : null;
    if (least !== null && least !== undefined) parts.push(`least ring t* = ${fmt(least, 5)} m`);
    $("geometry").textContent = parts.join("; ");
  }
  $("message").textContent = msg.join("  ");
}

// ---------------------------------------------------------------- the eta-mu diagram
function el(name, attrs, parent, text) {
  const e = document.createElementNS(SVG_NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  if (parent) parent.appendChild(e);
  return e;
}

function branchMode(modes, mu) {
  for (const b of modes.branches) {
    const hi = b.mu_max === null ? Infinity : b.mu_max;
    if (b.mu_min < hi && mu >= b.mu_min && mu <= hi) return b.mode;
  }
  return null;
}

function drawDiagram() {
  const box = $("diagram");
  box.innerHTML = "";
  $("legend").innerHTML = "";
  const W = 640, H = 380, L = 58, R = 16, T = 14, B = 44;
  const svg = el("svg", { viewBox: `0 0 ${W} ${H}`, class: "diagram" }, box);
  const { modes, curve, solve, assess } = state;
  if (!modes || !curve) {
    svg.setAttribute("viewBox", `0 0 ${W} 60`);
    const why = "no diagram for these inputs";
    el("text", { x: W / 2, y: 34, "text-anchor": "middle", class: "muted" }, svg, why);
    return;
  }
  const pts = curve.points.filter((p) => p.status === "ok" && p.eta !== undefined && p.eta !== null);
  for (const c of modes.corners) pts.push({ mu: c.mu, eta: c.eta, corner: true });
  pts.sort((a, b) => a.mu - b.mu);
  if (pts.length === 0) {
    el("text", { x: W / 2, y: H / 2, "text-anchor": "middle", class: "muted" }, svg, "no limit state in this range of μ");
    return;
  }
  // mu range: from below mu_ms to a few times the last corner, and the current mu
  const muNow = $("mu-inf").checked ? Infinity : Number($("mu").value);
  const knots = [pts[0].mu, ...modes.corners.map((c) => c.mu)];
  let muLo = pts[0].mu / 1.6;
  let muHi = Math.max(6 * Math.max(...knots), 12 * muLo);
  if (Number.isFinite(muNow) && muNow > 0) {
    muLo = Math.max(MU_LO / 1.2, Math.min(muLo, muNow / 1.25));
    muHi = Math.min(MU_HI * 1.2, Math.max(muHi, muNow * 1.25));
  }
  let etaMax = Math.max(...pts.map((p) => p.eta));
  if (assess && Number(assess.eta) > 0) etaMax = Math.max(etaMax, Number(assess.eta));
  etaMax = Math.min(2, etaMax * 1.25 || 1);
  const x = (mu) => L + ((Math.log(mu) - Math.log(muLo)) / (Math.log(muHi) - Math.log(muLo))) * (W - L - R);
  const y = (eta) => H - B - (eta / etaMax) * (H - T - B);
  const muOfX = (px) => Math.exp(Math.log(muLo) + ((px - L) / (W - L - R)) * (Math.log(muHi) - Math.log(muLo)));

  // regions: collapse / no equilibrium below the curve, standing above it
  const top = y(etaMax), bottom = y(0), left = x(muLo), right = x(muHi);
  const line = pts.map((p) => `${x(p.mu).toFixed(2)},${y(p.eta).toFixed(2)}`);
  const first = pts[0], last = pts[pts.length - 1];
  const clip = el("clipPath", { id: "plot-area" }, el("defs", {}, svg));
  el("rect", { x: left, y: top, width: right - left, height: bottom - top }, clip);
  const plot = el("g", { "clip-path": "url(#plot-area)" }, svg);
  el("rect", { x: left, y: top, width: right - left, height: bottom - top, class: "collapse" }, plot);
  el("polygon", {
    points: [`${x(first.mu)},${top}`, ...line, `${Math.max(x(last.mu), right)},${y(last.eta)}`, `${Math.max(x(last.mu), right)},${top}`].join(" "),
    class: "safe",
  }, plot);
  el("text", { x: right - 8, y: top + 18, "text-anchor": "end", class: "region" }, svg, "stands (η > η*)");
  el("text", { x: right - 8, y: bottom - 8, "text-anchor": "end", class: "region" }, svg, "collapses (η < η*)");
  if (modes.mu_ms) {
    const xm = (left + x(modes.mu_ms)) / 2 + 4, ym = (top + bottom) / 2;
    el("text", { x: xm, y: ym, "text-anchor": "middle", transform: `rotate(-90 ${xm} ${ym})`, class: "region" }, svg, "no equilibrium (μ < μ_ms)");
  }

  // axes
  const mantissas = Math.log10(muHi / muLo) < 1.2 ? [1, 1.5, 2, 3, 4, 5, 6, 8] : [1, 2, 5];
  for (let d = -3; d <= 3; d++) {
    for (const m of mantissas) {
      const mu = m * Math.pow(10, d);
      if (mu < muLo || mu > muHi) continue;
      el("line", { x1: x(mu), x2: x(mu), y1: top, y2: bottom, class: m === 1 ? "grid major" : "grid" }, svg);
      el("text", { x: x(mu), y: bottom + 16, "text-anchor": "middle", class: "tick" }, svg, String(Number(mu.toPrecision(3))));
    }
  }
  const step = etaMax > 1 ? 0.2 : etaMax > 0.4 ? 0.1 : etaMax > 0.2 ? 0.05 : 0.02;
  for (let e = 0; e <= etaMax + 1e-9; e += step) {
    el("line", { x1: left, x2: right, y1: y(e), y2: y(e), class: "grid" }, svg);
    el("text", { x: left - 6, y: y(e) + 4, "text-anchor": "end", class: "tick" }, svg, e.toFixed(2));
  }
  el("rect", { x: left, y: top, width: right - left, height: bottom - top, class: "frame" }, svg);
  el("text", { x: (left + right) / 2, y: H - 6, "text-anchor": "middle", class: "axis" }, svg, "friction coefficient μ (log scale)");
  el("text", { x: 14, y: (top + bottom) / 2, transform: `rotate(-90 14 ${(top + bottom) / 2})`, "text-anchor": "middle", class: "axis" }, svg, "η = t / r");

  // the curve, each piece coloured by the mode of its branch
  for (let i = 0; i + 1 < pts.length; i++) {
    const a = pts[i], b = pts[i + 1];
    const mid = Math.sqrt(a.mu * b.mu);
    const mode = branchMode(modes, mid) || b.mode || a.mode;
    el("line", { x1: x(a.mu), y1: y(a.eta), x2: x(b.mu), y2: y(b.eta), stroke: modeColour(mode), class: "curve" }, plot);
  }
  // vertical branches (purely sliding at mu_ms) up to the top
  for (const b of modes.branches) {
    if (b.mu_max !== null && b.mu_min === b.mu_max) {
      const e1 = b.eta_max === null ? etaMax : Math.min(b.eta_max, etaMax);
      el("line", { x1: x(b.mu_min), y1: y(b.eta_min), x2: x(b.mu_min), y2: y(e1), stroke: modeColour(b.mode), class: "curve" }, plot);
    }
  }
  for (const c of modes.corners) {
    const dot = el("circle", { cx: x(c.mu), cy: y(c.eta), r: 4.5, class: "corner" }, svg);
    el("title", {}, dot, `corner μ = ${fmt(c.mu)}, η = ${fmt(c.eta)} (${c.between.join(" / ")})`);
  }
  // the current state
  const xNow = Number.isFinite(muNow) ? x(Math.min(Math.max(muNow, muLo), muHi)) : right;
  el("line", { x1: xNow, x2: xNow, y1: top, y2: bottom, class: "now" }, svg);
  if (!Number.isFinite(muNow)) el("text", { x: right - 4, y: bottom - 24, "text-anchor": "end", class: "tick" }, svg, "μ = ∞ →");
  if (assess && assess.eta > 0 && assess.eta <= etaMax) {
    const d = el("rect", { x: xNow - 5, y: y(assess.eta) - 5, width: 10, height: 10, transform: `rotate(45 ${xNow} ${y(assess.eta)})`, class: assess.stands ? "assess ok" : "assess bad" }, svg);
    el("title", {}, d, `η = ${assess.eta}: ${assess.stands ? "stands" : "does not stand"}`);
  }
  if (solve && solve.eta !== undefined && solve.eta <= etaMax) {
    el("circle", { cx: xNow, cy: y(solve.eta), r: 6, class: "point", fill: modeColour(solve.mode) }, svg);
    el("text", { x: xNow + 9, y: y(solve.eta) - 9, class: "label" }, svg, `η* = ${fmt(solve.eta, 5)}`);
  }
  // click: set mu
  svg.addEventListener("click", (ev) => {
    const r = svg.getBoundingClientRect();
    const px = ((ev.clientX - r.left) / r.width) * W;
    if (px < left || px > right) return;
    setMu(Number(muOfX(px).toPrecision(4)));
  });

  // legend: the modes on this curve
  const legend = $("legend");
  const seen = new Set(modes.sampled ? pts.map((p) => p.mode).filter(Boolean) : modes.branches.map((b) => b.mode));
  for (const m of seen) {
    const item = document.createElement("span");
    item.className = "item";
    const sw = document.createElement("i");
    sw.style.background = modeColour(m);
    item.append(sw, m.replaceAll("_", " "));
    legend.appendChild(item);
  }
  const c = document.createElement("span");
  c.className = "item";
  if (modes.sampled) c.textContent = "with fill: η*(μ) sampled at 100 μ (no exact corners; μ_ms depends on η)";
  else c.innerHTML = '<b class="cornerkey"></b>corner (exact)';
  legend.appendChild(c);
}

// ---------------------------------------------------------------- wiring
const stateSoon = debounce(() => { clearErrors(); refreshState(); }, 120);
const allSoon = debounce(() => { clearErrors(); refreshCurve(); refreshState(); }, 200);

function setMu(mu) {
  $("mu-inf").checked = false;
  $("mu").value = String(mu);
  $("mu-slider").value = String(sliderOfMu(mu));
  stateSoon();
}

function wire() {
  $("mu-lo").textContent = `μ = ${MU_LO}`;
  $("mu-hi").textContent = `${MU_HI}`;
  $("mu-slider").value = String(sliderOfMu(Number($("mu").value)));
  $("mu-slider").addEventListener("input", () => {
    $("mu-inf").checked = false;
    $("mu").value = String(muOfSlider(Number($("mu-slider").value)));
    stateSoon();
  });
  $("mu").addEventListener("input", () => {
    const v = Number($("mu").value);
    if (v > 0) $("mu-slider").value = String(sliderOfMu(v));
    $("mu-inf").checked = false;
    stateSoon();
  });
  $("mu-inf").addEventListener("change", stateSoon);
  $("alpha-slider").addEventListener("input", () => {
    $("alpha-deg").value = $("alpha-slider").value;
    allSoon();
  });
  $("alpha-deg").addEventListener("input", () => {
    $("alpha-slider").value = $("alpha-deg").value;
    allSoon();
  });
  $("eta-slider").addEventListener("input", () => {
    $("eta").value = String(Number($("eta-slider").value) / 1000);
    stateSoon();
  });
  $("eta").addEventListener("input", () => {
    $("eta-slider").value = String(Math.round(Number($("eta").value) * 1000));
    stateSoon();
  });
  for (const id of ["beta-right", "beta-left", "span", "rise", "blocks", "weight"]) $(id).addEventListener("input", allSoon);
  $("ring").addEventListener("input", stateSoon);
  for (const id of ["unit-weight", "width", "fill-weight", "fill-depth", "fill-ratio", "fill-height", "axles", "spacing", "at"]) {
    $(id).addEventListener("input", stateSoon);
  }
  $("fill").addEventListener("change", () => {
    showShape();
    allSoon();
  });
  $("critical").addEventListener("change", () => {
    $("at-row").hidden = $("critical").checked;
    stateSoon();
  });
  document.querySelectorAll('input[name="shape"], input[name="joints"]').forEach((r) => r.addEventListener("change", () => {
    showShape();
    allSoon();
  }));
  $("load").addEventListener("change", () => {
    $("point-row").hidden = $("load").value !== "point-load-deg";
    $("vehicle-rows").hidden = !isVehicle();
    if (isVehicle()) selectFigure("influence");
    else if ($("load").value !== "none" && !hasFill()) selectFigure("load");
    stateSoon();
  });
  $("point-load-deg").addEventListener("input", stateSoon);
  document.querySelectorAll(".tab").forEach((t) => t.addEventListener("click", () => {
    selectFigure(t.dataset.fig);
    stateSoon();
  }));
  // the figures are drawn 960 px wide: beside the diagram their text is small, enlarged it
  // spans the diagram's column too (three-column layout only; below it spans the page)
  $("enlarge").addEventListener("click", () => {
    const wide = document.querySelector("main").classList.toggle("wide-figure");
    $("enlarge").setAttribute("aria-pressed", String(wide));
    $("enlarge").textContent = wide ? "beside the diagram" : "enlarge";
  });
  showShape();
  refreshCurve();
  refreshState();
}

function showShape() {
  const shape = document.querySelector('input[name="shape"]:checked').value;
  document.querySelectorAll("[data-shape]").forEach((r) => r.classList.toggle("off", r.dataset.shape !== shape));
  const which = shape === "metres" ? "ring" : "eta";
  document.querySelectorAll("[data-thickness]").forEach((r) => (r.hidden = r.dataset.thickness !== which));
  $("blocks").disabled = document.querySelector('input[name="joints"]:checked').value !== "blocks";
  document.querySelectorAll("[data-fill]").forEach((r) => (r.hidden = !hasFill() || r.dataset.fill !== (shape === "metres" ? "metres" : "ratio")));
  // a vehicle's axles are in kN: the arch in metres
  const vehicle = document.querySelector('#load option[value="vehicle"]');
  vehicle.disabled = shape !== "metres";
  if (vehicle.disabled && isVehicle()) {
    $("load").value = "none";
    $("vehicle-rows").hidden = true;
  }
  $("at-row").hidden = $("critical").checked;
}

wire();
