// pipeline/report_page_panels.js: the report page's script, second half (after report_page.js, in the
// same script element): the inspector, the input and memory tables, the PS2 time bars, the ledger and
// the start.
// ---- the inspector ----
function colour87(r, name) {  // the fragment colour r, g, b, a in 8.7 fixed point
  const c = PX.col(name);
  return [0, 1, 2, 3].map(k => hex(c(r, k), 4)).join(" ");
}
function inspect(x, y) {
  selected = [x, y];
  placeMarks();
  const box = $("inspector");
  box.replaceChildren();
  const data = (key, text) => el("td", {"data-k": key, class: "mono"}, text);
  box.append(el("p", {}, `pixel x ${x}, y ${y}`));
  if (!PX) { box.append(el("p", {}, "No per-pixel data: " + check.pixels)); return; }
  const r = PX.rowOf[y * W + x];
  if (r < 0) { box.append(el("p", {"data-k": "uncovered"}, "not covered by the mesh (every method leaves the DPB at its clear value here)")); return; }
  const u = PX.col("u16")(r), v = PX.col("v16")(r), ti = PX.col("texel_index")(r), n = P.palette[ti];
  const inputs = el("table", {}, el("tr", {}, el("th", {class: "l"}, "input"), el("th", {class: "l"}, "value")));
  const add = (t, label, cell) => t.append(el("tr", {}, el("td", {class: "l"}, label), cell));
  add(inputs, "visible triangle", data("triangle", String(PX.col("triangle")(r))));
  add(inputs, "UV (12.4 texels)", data("uv", `${hex(u, 5)} ${hex(v, 5)} = (${fixed(u / 16, 4)}, ${fixed(v / 16, 4)})`));
  add(inputs, "normal-map texel (nearest) → palette entry", data("texel_index", `${ti} → (${n.map(q => fixed(q, 4)).join(", ")})`));
  for (let l = 0; l < LIGHTS; ++l) {
    add(inputs, `float reference light ${l}: 128·fade·N·normalize(L)`, data("reference/dot" + l, fixed(PX.col("reference/dot" + l)(r), 3)));
    add(inputs, `float reference light ${l}: 128·N·L`, data("reference/unnormalised" + l, fixed(PX.col("reference/unnormalised" + l)(r), 3)));
  }
  box.append(inputs);
  for (const name of methodNames) {
    const passes = (P.passes || {})[name];
    box.append(el("h3", {}, name + (R.methods[name].seed ? " (seed " + R.methods[name].seed + ")" : "")));
    const t = el("table", {"data-method": name});
    if (!passes) {  // a scheme method: its dot products
      t.append(el("tr", {}, el("th", {class: "l"}, "light"), el("th", {}, "dot (1/128)"), el("th", {}, "− reference")));
      for (let l = 0; l < LIGHTS; ++l)
        t.append(el("tr", {}, el("td", {class: "l"}, String(l)), data(name + "/dot" + l, fixed(dotAt(name, r, l), 3)),
                    el("td", {}, fixed(dotAt(name, r, l) - dotAt("reference", r, l), 3))));
      box.append(t);
      continue;
    }
    t.append(el("tr", {}, ...["pass", "light", "target", "texel (ABGR)", "fragment colour R G B A (8.7)", "word after (ABGR)", "R byte"].map((h, i) => el("th", {class: i < 3 ? "l" : ""}, h))));
    passes.forEach((p, i) => {
      const key = `${name}/${i}/`, shaded = PX.col(key + "shaded")(r);
      const word = PX.col(key + "word")(r);
      t.append(el("tr", {}, el("td", {class: "l"}, p.label), el("td", {class: "l"}, p.light < 0 ? "" : String(p.light)), el("td", {class: "l"}, p.target),
                  data(key + "texel", shaded ? hex(PX.col(key + "texel")(r), 8) : "—"),
                  data(key + "colour", shaded ? colour87(r, key + "colour") : "—"),
                  data(key + "word", hex(word, 8)), el("td", {class: "mono"}, hex(word & 0xFF, 2))));
    });
    box.append(t);
    const s = el("table", {}, el("tr", {}, ...["light", "post-filter sum (DPB R)", "dot = sum − 128", "− reference", "ILP entry (ABGR)", "LAB after"].map(h => el("th", {}, h))));
    for (let l = 0; l < LIGHTS; ++l) {
      const sum = PX.col(name + "/dot" + l)(r);
      const lab = passes.findIndex(p => p.target === "LAB" && p.light === l);
      s.append(el("tr", {}, el("td", {}, String(l)), data(name + "/sum" + l, hex(sum, 2)), data(name + "/dotvalue" + l, String(dotAt(name, r, l))),
                  el("td", {}, fixed(dotAt(name, r, l) - dotAt("reference", r, l), 3)),
                  data(name + "/ilp" + l, lab < 0 ? "—" : hex(PX.col(`${name}/${lab}/texel`)(r), 8)),
                  data(name + "/lab" + l, lab < 0 ? "—" : hex(PX.col(`${name}/${lab}/word`)(r), 8))));
    }
    box.append(s);
  }
  check.inspected = [x, y];
}

// ---- what was read (report.json "input") and the GS local memory (report.json "memory") ----
function valueText(v) {
  if (v === null || v === undefined) return "—";
  if (Array.isArray(v)) return v.length ? v.map(valueText).join("; ") : "none";
  if (typeof v === "object") return Object.entries(v).map(([k, x]) => k + ": " + valueText(x)).join(", ");
  return String(v);
}
if (R.input) {
  const t = el("table", {}, el("tr", {}, el("th", {class: "l"}, "input"), el("th", {class: "l"}, "what was read, generated or repaired")));
  for (const [k, v] of Object.entries(R.input)) t.append(el("tr", {}, el("td", {class: "l"}, k), el("td", {class: "l"}, valueText(v))));
  $("input").append(el("h2", {}, "Input"), t);
}
if (R.memory) {
  const m = $("memory");
  m.append(el("h2", {}, "GS local memory"),
           el("p", {}, "A PSMCT32 page (the DPB) read as PSMT8, the post filter's texture (red, green, blue, grey: the R, G, B, " +
                       "A byte of a pixel), and as PSMZ32 (colour: the PSMCT32 pixel's position)."));
  const pics = el("p", {class: "gallery"});
  for (const f of R.memory.pictures || []) pics.append(el("img", {src: f, alt: f, title: f}));
  m.append(pics);
  const dp = R.memory.dpb_pictures;
  if (dp) {
    m.append(el("p", {}, "The DPB of this " + dp.method + " frame (rendered on the memory path) as light 0's post filter reads " +
                         "it: as the GS displays the PSMCT32 buffer, and the same memory read as the PSMT8 texture (TBW = 2·FBW) " +
                         "whose texels the channel-fetch sprites pick."));
    const dpics = el("p", {class: "gallery"});
    for (const f of dp.files || []) dpics.append(el("img", {src: f, alt: f, title: f}));
    m.append(dpics);
  }
  if (R.memory.steps) {
    const t = el("table", {id: "memory-steps"}, el("tr", {}, ...["step", "what it does", "memory path", "value path"].map(h => el("th", {class: "l"}, h))));
    for (const st of R.memory.steps)
      t.append(el("tr", {}, el("td", {class: "l"}, st.step), el("td", {class: "l"}, st.does),
                  el("td", {class: "l", "data-k": "memory-step-" + st.step}, st.memory_path), el("td", {class: "l"}, st.value_path)));
    m.append(el("p", {}, "Section 3.1 step by step: how each step is modelled on each path."), t);
  }
  const eq = R.memory.memory_path_equals_value_level;
  if (eq) m.append(el("p", {}, "Memory path = value level, bit for bit: " +
                       Object.entries(eq).map(([k, v]) => k + " " + (v ? "yes" : "NO")).join(", ") + "."));
}

// ---- PS2 time per method (report --cost): one stacked bar per method, where its GS cycles go ----
if (R.ps2) {
  const parts = [["pixels", "pixels", "#4a7"], ["page_breaks", "page breaks", "#c84"], ["texture_misses", "texture misses", "#a6c"],
                 ["uploads", "uploads", "#69c"], ["clut_loads", "CLUT loads", "#cc4"], ["setup", "set-up", "#999"]];
  const priced = methodNames.filter(n => R.methods[n].ps2 && R.methods[n].ps2.cycles !== undefined);
  const field = 147456000 / 59.94;  // GS cycles in an NTSC field
  const most = Math.max(field, ...priced.map(n => R.methods[n].ps2.cycles));
  const rowH = 26, left = 110, right = 380, width = left + 560 + right, scale = 560 / most;
  let svg = `<svg width="${width}" height="${rowH * (priced.length + 1) + 10}" ` +
            `font-family="sans-serif" font-size="12" role="img" aria-label="PS2 GS time per method">`;
  priced.forEach((n, i) => {
    const c = R.methods[n].ps2, y = 4 + i * rowH;
    let x = left;
    svg += `<text x="${left - 6}" y="${y + 15}" text-anchor="end">${n}</text>`;
    for (const [k, label, colour] of parts) {
      const w = c.breakdown[k] * scale;
      svg += `<rect class="ps2-part" x="${x}" y="${y}" width="${w}" height="${rowH - 6}" fill="${colour}">` +
             `<title>${n}: ${label} ${c.breakdown[k]} cycles (${fixed(100 * c.breakdown[k] / c.cycles, 1)} %)</title></rect>`;
      x += w;
    }
    const err = R.methods[n].vs_renormalised;
    svg += `<text x="${x + 6}" y="${y + 15}">${fixed(c.seconds * 1e3, 3)} ms, ${fixed(100 * c.ntsc.budget_share, 1)} % of an NTSC field` +
           ` · RMSE ${fixed(err.rmse, 2)} /128</text>`;
    ++check.ps2_bars;
  });
  const fx = left + field * scale, fy = rowH * priced.length + 4;
  svg += `<line x1="${fx}" y1="0" x2="${fx}" y2="${fy}" stroke="#000" stroke-dasharray="4 3"/>` +
         `<text x="${fx}" y="${fy + 12}" text-anchor="middle">one NTSC field (16.7 ms)</text></svg>`;
  const legend = el("p", {}, "Cycles by where they go: ");
  for (const [, label, colour] of parts)
    legend.append(el("span", {class: "badge", style: "background:" + colour}, label), " ");
  const box = $("ps2");
  box.append(el("h2", {}, "PS2 time per method (GS cost model)"),
             el("p", {}, "Each GS method's frame as the GIF stream gsdot3 dump writes, priced by the GS cost model " +
                         "(src/gs_cost, docs/cost.md) at 147.456 MHz with " +
                         Object.entries(R.ps2.options).map(([k, v]) => k + "=" + v).join(", ") +
                         "; beside it the method's error against the renormalised reference. Hover a segment for its cycles."),
             legend);
  const chart = el("div", {id: "ps2-chart"});
  chart.innerHTML = svg;
  box.append(chart);
  if (R.performance_claims) {
    const t = el("table", {id: "performance-claims"},
                 el("tr", {}, ...["claim", "paper", "sentence", "figures on this scene", "verdict"].map(h => el("th", {class: "l"}, h))));
    for (const r of R.performance_claims)
      t.append(el("tr", {}, el("td", {class: "l mono"}, r.claim), el("td", {class: "l"}, r.paper), el("td", {class: "l"}, r.statement),
                  el("td", {class: "l"}, r.figures),
                  el("td", {class: "l"}, el("span", {class: "badge " + (r.verdict === "holds" ? "proven" : r.verdict === "refuted" ? "refuted" : "bound")}, r.verdict))));
    box.append(el("h3", {}, "The paper's performance sentences priced on this scene (gsdot3 cost --claims: docs/performance-claims.md)"), t);
  }
  const missing = methodNames.filter(n => R.methods[n].ps2 && R.methods[n].ps2.not_priced);
  for (const n of missing) box.append(el("p", {}, n + " not priced: " + R.methods[n].ps2.not_priced));
}

// ---- proof ledger and gallery ----
{
  const cited = {};
  for (const name of methodNames) for (const id of (P.methods[name] || {}).claims || []) (cited[id] = cited[id] || []).push(name);
  const t = el("table", {}, el("tr", {}, ...["claim", "paper", "statement", "verdict", "option changes", "methods"].map(h => el("th", {class: "l"}, h))));
  for (const [id, names] of Object.entries(cited)) {
    const c = P.claims[id] || {};
    t.append(el("tr", {id: "claim-" + id}, el("td", {class: "l mono"}, id, el("br"), el("small", {}, "docs/claims.md#" + (c.anchor || "?"))),
                el("td", {class: "l"}, c.paper || ""), el("td", {class: "l"}, c.statement || "not in the catalogue"),
                el("td", {class: "l"}, el("span", {class: "badge " + verdictClass(c.verdict)}, c.verdict || "?")),
                el("td", {class: "l"}, c.option_changes || ""), el("td", {class: "l"}, names.join(", "))));
  }
  $("ledger").append(t);
  if (R.quality_claims) {
    const q = el("table", {}, el("tr", {}, ...["claim", "metric", "claimed better", "other", "verdict on this scene"].map(h => el("th", {class: "l"}, h))));
    for (const r of R.quality_claims)
      q.append(el("tr", {}, el("td", {class: "l mono"}, r.claim), el("td", {class: "l mono"}, r.metric),
                  el("td", {class: "l"}, r.better + " " + (+r.value_better).toPrecision(4)), el("td", {class: "l"}, r.other + " " + (+r.value_other).toPrecision(4)),
                  el("td", {class: "l"}, el("span", {class: "badge " + verdictClass(r.verdict)}, r.verdict))));
    $("ledger").append(el("h3", {}, "The paper's comparative sentences on this scene (gsdot3 quality: also seeded random scenes; docs/quality-claims.md)"), q);
  }
  const g = $("gallery");
  const all = [...methodNames.map(n => [n, P.methods[n].images]), ["reference", P.reference_images]];
  for (const [n, im] of all) {
    g.append(el("h3", {}, n + (R.methods[n] && R.methods[n].summary ? ": " + R.methods[n].summary : "")));
    for (const f of [im.lit, ...im.dot, ...im.error]) g.append(el("img", {src: f, alt: f, title: f}));
  }
  if (P.side_by_side) g.append(el("h3", {}, "Side by side (after the paper's figure 7): top front, bottom back; left two-pass, right four-pass"),
                               el("img", {src: P.side_by_side, alt: "side by side", style: "max-width:100%"}));
}

// ---- start: load the per-pixel data, apply the URL hash (#a=..&b=..&layer=..&light=..&zoom=..&x=..&y=..&selftest=1) ----
function loadScript(src) {
  return new Promise((ok, fail) => { const s = el("script", {src}); s.onload = ok; s.onerror = () => fail(new Error(src + " did not load")); document.head.append(s); });
}
async function start() {
  update();
  if (firstPin) { pinned = true; inspect(...firstPin); centre(...firstPin); }
  if (P.pixels_file) {
    try { await loadScript(P.pixels_file); PX = await decodePixels(window.gsdot3_pixels); check.pixels = "loaded " + PX.count + " pixels"; }
    catch (e) { check.pixels = String(e.message || e); }
  } else check.pixels = "the report was written without per-pixel data";
  drawDiff();
  if (params.has("selftest")) {  // the browser test: switch the picker through every pair of neighbours
    for (let i = 0; i < choices.length; ++i) {
      const a = choices[i], b = choices[(i + 1) % choices.length];
      $("pick-a").value = a; $("pick-b").value = b;
      $("pick-a").dispatchEvent(new Event("change"));
      const nonzero = drawDiff();
      check.picker.push({a, b, src_a: $("img-a").getAttribute("src"), src_b: $("img-b").getAttribute("src"), title_d: $("title-d").textContent, diff_nonzero: nonzero});
    }
    $("pick-a").value = params.get("a") || defaultA; $("pick-b").value = params.get("b") || "reference";
    update();
  }
  if (firstPin) inspect(...firstPin);
  const imgs = [...document.images];
  await Promise.all(imgs.map(i => i.decode().then(() => ++check.images.loaded, () => check.images.failed.push(i.getAttribute("src")))));
  check.images.total = imgs.length;
  $("selfcheck").textContent = JSON.stringify(check);
  document.body.setAttribute("data-ready", "1");
}
start();
