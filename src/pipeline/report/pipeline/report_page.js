// pipeline/report_page.js: the report page's script, first half (report_page.cpp puts it and
// report_page_panels.js, in this order, into one script element of report_page.html): the data, the
// error tables, the heat colours, the per-pixel data, the picker and the overview of the first screen.
"use strict";
const R = JSON.parse(document.getElementById("gsdot3-report").textContent);
const P = JSON.parse(document.getElementById("gsdot3-page").textContent);
const W = R.scene.width, H = R.scene.height, LIGHTS = R.scene.lights;
const check = {errors: [], images: {total: 0, loaded: 0, failed: []}, pixels: "loading report-pixels.js", picker: [], inspected: null, ps2_bars: 0};
window.addEventListener("error", e => check.errors.push(String(e.message || e.type)));
window.addEventListener("unhandledrejection", e => check.errors.push("unhandled rejection: " + String(e.reason)));
const $ = id => document.getElementById(id);
const el = (tag, attrs, ...kids) => {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) if (k === "class") e.className = v; else e.setAttribute(k, v);
  for (const k of kids) e.append(k);
  return e;
};
const hex = (v, digits) => "0x" + (v >>> 0).toString(16).padStart(digits, "0");
const fixed = (v, d) => Number(v).toFixed(d);
const methodNames = Object.keys(R.methods);
const paperMethods = ["two-pass", "four-pass"].filter(n => n in R.methods);  // the paper's, shown first
const params = new URLSearchParams(location.hash.slice(1));

// ---- scene line and error tables (one row per method, sortable) ----
{
  const s = R.scene, o = R.options;
  $("scene").textContent = `Scene: ${s.description}, ${s.width}×${s.height}, ${s.drawn_triangles} of ${s.triangles} triangles drawn, ` +
    `${s.lights} lights, normal map ${s.normal_map.width}×${s.normal_map.height} (${s.normal_map.palette} palette entries), ` +
    `s = ${o.s}, filter ${o.filter}${o.specular ? ", specular (ILP power " + o.specular_power + ")" : ""}; model options: ` +
    Object.entries(o.model).map(([k, v]) => k + "=" + v).join(", ") + ".";
}
const verdictClass = v => (v || "").startsWith("proven") ? "proven" : (v || "").startsWith("refuted") ? "refuted" :
  (v || "").startsWith("bound") ? "bound" : "missing";
function claimBadges(name) {
  const span = el("span");
  for (const id of (P.methods[name] || {}).claims || []) {
    const c = P.claims[id] || {verdict: "unknown claim"};
    span.append(el("a", {class: "badge " + verdictClass(c.verdict), href: "#claim-" + id, title: c.statement || ""}, id + ": " + c.verdict));
  }
  return span;
}
const statCols = [["samples", "samples", 0], ["max_abs", "max |e|", 2], ["mean", "mean e", 3], ["mean_abs", "mean |e|", 3],
                  ["rmse", "RMSE", 3], ["psnr_db", "PSNR dB", 2], ["within_1", "within ±1 %", 2], ["wrap_errors", "wrap errors", 0]];
function statsTable(key, title) {
  const t = el("table", {"data-table": key});
  const head = el("tr", {}, el("th", {class: "l"}, "method"), el("th", {class: "l"}, "seed"), el("th", {}, "frame ms"));
  for (const [, label] of statCols) head.append(el("th", {}, label));
  head.append(el("th", {class: "l"}, "claims (verdict)"));
  t.append(head);
  for (const name of methodNames) {
    const m = R.methods[name], st = m[key];
    const row = el("tr", {"data-method": name}, el("td", {class: "l"}, name), el("td", {class: "l"}, m.seed ? m.seed + (m.compared_with === "reference" ? "" : " (vs " + m.compared_with + ")") : "GS (Mikkelsen 2004)"),
                   el("td", {"data-v": m.frame_seconds * 1000}, fixed(m.frame_seconds * 1000, 1)));
    for (const [k, , d] of statCols) {
      const raw = st[k] === "inf" ? Infinity : k === "within_1" ? 100 * st[k] : st[k];
      row.append(el("td", {"data-v": raw}, raw === Infinity ? "inf" : fixed(raw, d)));
    }
    row.append(el("td", {class: "l"}, claimBadges(name)));
    t.append(row);
  }
  head.querySelectorAll("th").forEach((th, col) => th.addEventListener("click", () => {
    const asc = !th.classList.contains("sorted-asc");
    head.querySelectorAll("th").forEach(h => h.classList.remove("sorted-asc", "sorted-desc"));
    th.classList.add(asc ? "sorted-asc" : "sorted-desc");
    const rows = [...t.querySelectorAll("tr[data-method]")];
    const val = r => { const c = r.children[col]; return c.hasAttribute("data-v") ? Number(c.getAttribute("data-v")) : c.textContent; };
    rows.sort((x, y) => { const a = val(x), b = val(y); const r = typeof a === "number" ? a - b : String(a).localeCompare(String(b)); return asc ? r : -r; });
    rows.forEach(r => t.append(r));
  }));
  return [el("h3", {}, title), t];
}
$("tables").append(...statsTable("vs_renormalised", "Against the renormalised float reference (128·fade·N·normalize(L))"),
                   ...statsTable("vs_unnormalised", "Against the float reference without renormalisation (128·N·L)"));
{
  const n = R.reference.normalisation_error;
  $("tables").append(el("p", {}, `Normalisation error of the float reference itself (not renormalised − renormalised): max |e| ${fixed(n.max_abs, 2)}, ` +
    `RMSE ${fixed(n.rmse, 3)} over ${n.samples} samples; float reference ${fixed(R.reference.seconds * 1000, 1)} ms.`));
  if (R.reference.warning) $("tables").append(el("p", {class: "warning"}, "Why the errors are large: " + R.reference.warning + "."));
}

// ---- heat colours, the same as report.cpp's error maps ----
const LIMIT = P.heat_limit;
function heat(e) {
  const t = Math.min(Math.max(Math.abs(e) / LIMIT, 0), 1), f = Math.round(255 * (1 - t));
  return e >= 0 ? [255, f, f] : [f, f, 255];
}
{
  const c = $("legend"), g = c.getContext("2d"), img = g.createImageData(c.width, c.height);
  for (let x = 0; x < c.width; ++x) {
    const e = (2 * x / (c.width - 1) - 1) * LIMIT;
    const unit = Math.abs(e - Math.round(e)) * (c.width - 1) / (2 * LIMIT);
    for (let y = 0; y < c.height; ++y) {
      const tick = unit < 0.5 && (y < 8 || Math.round(e) === 0);
      const col = tick ? [0, 0, 0] : heat(e);
      img.data.set([...col, 255], 4 * (y * c.width + x));
    }
  }
  g.putImageData(img, 0, 0);
  $("legend-text").textContent = `−${LIMIT} … 0 … +${LIMIT} /128 (saturating; a tick per unit; dark grey: not covered)`;
}

// ---- per-pixel data (report-pixels.js) ----
let PX = null;  // {count, col(name) -> (row, k) -> value, row of pixel index}
async function decodePixels(d) {
  const bin = atob(d.deflate_base64), bytes = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; ++i) bytes[i] = bin.charCodeAt(i);
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("deflate"));
  const view = new DataView(await new Response(stream).arrayBuffer());
  const size = {u8: 1, u16: 2, u32: 4, i32: 4, f32: 4};
  const get = {u8: (o) => view.getUint8(o), u16: (o) => view.getUint16(o, true), u32: (o) => view.getUint32(o, true),
               i32: (o) => view.getInt32(o, true), f32: (o) => view.getFloat32(o, true)};
  const cols = {};
  for (const c of d.columns) {
    if ("const" in c) cols[c.name] = Array.isArray(c.const) ? (r, k = 0) => c.const[k] : () => c.const;
    else if ("same_as" in c) cols[c.name] = cols[c.same_as];
    else { const g = get[c.type], s = size[c.type], w = c.width, o0 = c.offset; cols[c.name] = (r, k = 0) => g(o0 + (r * w + k) * s); }
  }
  const rowOf = new Int32Array(W * H).fill(-1);
  for (let r = 0; r < d.count; ++r) rowOf[cols.pixel(r)] = r;
  return {count: d.count, col: name => cols[name], has: name => name in cols, rowOf};
}
// A method's dot product (1/128 units) at row r and light l: GS bytes as signed (v − 128), floats as is.
function dotAt(name, r, l) {
  if (name === "reference") return PX.col("reference/dot" + l)(r);
  const v = PX.col(name + "/dot" + l)(r);
  return R.methods[name] && !R.methods[name].seed ? ((v - 128) << 24) >> 24 : v;
}

// ---- the picker: side by side and the difference map ----
const choices = [...methodNames, "reference"];
for (const id of ["pick-a", "pick-b"]) for (const n of choices) $(id).append(el("option", {value: n}, n === "reference" ? "float reference" : n));
for (let l = 0; l < LIGHTS; ++l) $("light").append(el("option", {value: l}, "light " + l));
const defaultA = paperMethods[0] || methodNames[0];
$("pick-a").value = params.get("a") || defaultA;
$("pick-b").value = params.get("b") || "reference";
// The pixel pinned on opening: the link's, else the worst of method A against the reference (report_page.cpp).
const worst = (P.methods[$("pick-a").value] || {}).worst;
const firstPin = params.has("x") ? [Number(params.get("x")), Number(params.get("y"))] : worst ? [worst.x, worst.y] : null;
if (params.get("layer")) $("layer").value = params.get("layer");
$("light").value = params.get("light") || (worst && !params.has("x") ? worst.light : 0);
$("zoom").value = params.get("zoom") || "2";
function imageFor(name, layer, l) {
  const im = name === "reference" ? P.reference_images : P.methods[name].images;
  if (layer === "lit") return im.lit;
  if (layer === "error" && im.error.length) return im.error[l];
  return im.dot[l];
}
let selected = null, pinned = false;
function placeMarks() {
  const z = Number($("zoom").value);
  document.querySelectorAll(".mark").forEach(m => {
    m.hidden = !selected;
    if (!selected) return;
    Object.assign(m.style, {left: selected[0] * z - 1 + "px", top: selected[1] * z - 1 + "px", width: z + "px", height: z + "px"});
  });
  document.querySelectorAll(".pin").forEach(p => {
    p.hidden = !selected;
    if (selected) Object.assign(p.style, {left: 100 * (selected[0] + 0.5) / W + "%", top: 100 * (selected[1] + 0.5) / p.dataset.h + "%"});
  });
}
function centre(x, y) {  // scrolls the views so that pixel (x, y) is in their middle, as far as their edges allow
  const z = Number($("zoom").value);
  for (const id of ["scroll-a", "scroll-b", "scroll-d"])
    Object.assign($(id), {scrollLeft: (x + 0.5) * z - $(id).clientWidth / 2, scrollTop: (y + 0.5) * z - $(id).clientHeight / 2});
}
function drawDiff() {
  const a = $("pick-a").value, b = $("pick-b").value, l = Number($("light").value);
  $("title-d").textContent = `difference ${a} − ${b}, light ${l}`;
  const c = $("diff");
  c.width = W; c.height = H;
  const g = c.getContext("2d"), img = g.createImageData(W, H);
  for (let i = 0; i < W * H; ++i) img.data.set([0x30, 0x30, 0x30, 255], 4 * i);
  if (!PX) { g.putImageData(img, 0, 0); return 0; }
  let nonzero = 0;
  for (let r = 0; r < PX.count; ++r) {
    const e = dotAt(a, r, l) - dotAt(b, r, l);
    if (e !== 0) ++nonzero;
    img.data.set([...heat(e), 255], 4 * PX.col("pixel")(r));
  }
  g.putImageData(img, 0, 0);
  return nonzero;
}
function update() {
  const a = $("pick-a").value, b = $("pick-b").value, layer = $("layer").value, l = Number($("light").value), z = Number($("zoom").value);
  $("img-a").src = imageFor(a, layer, l);
  $("img-b").src = imageFor(b, layer, l);
  $("title-a").textContent = `A: ${a} (${$("img-a").getAttribute("src")})`;
  $("title-b").textContent = `B: ${b} (${$("img-b").getAttribute("src")})`;
  const nonzero = drawDiff();
  const errH = layer === "error" ? H + 20 : H;  // error maps carry the legend strip below the frame
  for (const [id, h] of [["img-a", a === "reference" && layer === "error" ? H : errH], ["img-b", b === "reference" && layer === "error" ? H : errH], ["diff", H]])
    Object.assign($(id).style, {width: W * z + "px", height: h * z + "px"});
  placeMarks();
  return nonzero;
}
["pick-a", "pick-b", "layer", "light", "zoom"].forEach(id => $(id).addEventListener("change", () => {
  update();
  if (selected) { inspect(...selected); if (id === "zoom") centre(...selected); }
}));
for (const id of ["scroll-a", "scroll-b", "scroll-d"]) {
  const s = $(id);
  s.addEventListener("scroll", () => { for (const o of ["scroll-a", "scroll-b", "scroll-d"]) if (o !== id) { $(o).scrollLeft = s.scrollLeft; $(o).scrollTop = s.scrollTop; } });
  const target = s.firstElementChild;
  const at = e => {  // from the client position: offsetX is rounded to whole CSS pixels at fractional layout positions
    const z = Number($("zoom").value), b = target.getBoundingClientRect();
    return [Math.floor((e.clientX - b.left) / z), Math.floor((e.clientY - b.top) / z)];
  };
  target.addEventListener("mousemove", e => { const [x, y] = at(e); $("status").textContent = `x ${x}, y ${y}` + (pinned ? " (pinned; click to unpin)" : ""); if (!pinned && x < W && y < H) inspect(x, y); });
  target.addEventListener("click", e => { const [x, y] = at(e); if (x < W && y < H) { pinned = !pinned || selected[0] !== x || selected[1] !== y; inspect(x, y); } });
}

// ---- the overview: the paper's methods' lit frames, the float reference's and A's error map, the pinned pixel ----
{
  const a = $("pick-a").value, l = Number($("light").value), errorH = a === "reference" ? H : H + 20;
  const shown = [...(paperMethods.length ? paperMethods : [defaultA]).map(n => [P.methods[n].images.lit, H, n + ": lit frame"]),
                 [P.reference_images.lit, H, "float reference: lit frame"],
                 [imageFor(a, "error", l), errorH, `${a} − float reference, light ${l}`]];
  for (const [src, h, caption] of shown) {
    const img = el("img", {src, alt: caption, title: caption + " (click to inspect a pixel)", style: "width:100%;height:100%"});
    const pic = el("div", {style: `position:relative;max-width:${250 * W / h}px;aspect-ratio:${W} / ${h}`}, img,
                   el("span", {class: "pin", "data-h": h, hidden: ""}));
    img.addEventListener("click", e => {
      const b = img.getBoundingClientRect(), x = Math.floor((e.clientX - b.left) / b.width * W), y = Math.floor((e.clientY - b.top) / b.height * h);
      if (x < W && y < H) { pinned = true; inspect(x, y); centre(x, y); }
    });
    $("overview").append(el("figure", {}, pic, el("figcaption", {}, caption)));
  }
  if (params.has("x")) $("worst").textContent = `Pixel x ${firstPin[0]}, y ${firstPin[1]} of the link, pinned in the inspector below.`;
  else if (worst)
    $("worst").textContent = `Worst pixel of ${a} against the float reference: x ${worst.x}, y ${worst.y}, light ${worst.light}, ` +
      `error ${worst.error > 0 ? "+" : ""}${fixed(worst.error, 2)}/128, pinned in the inspector below (click a picture or a view to inspect another pixel).`;
}
