// The experiments report: reads bench/results/* and draws SVG plots (no plotting library). Text goes in with
// textContent and SVG nodes with createElementNS, never through innerHTML.
const SVG = 'http://www.w3.org/2000/svg';
const COLORS = ['#3d7dd8', '#e0823d', '#3aa0a0', '#c0392b', '#7d5ba6', '#8a8f98', '#f2c14e', '#2e7d32', '#d45d79'];

function h<K extends keyof HTMLElementTagNameMap>(tag: K, text?: string, cls?: string): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  if (text !== undefined) e.textContent = text;
  if (cls) e.className = cls;
  return e;
}
function s(tag: string, attrs: Record<string, string | number>, text?: string): SVGElement {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
}

interface Series {
  name: string;
  points: [number, number][];
  dash?: boolean;
}
interface PlotOptions {
  title: string;
  xLabel: string;
  yLabel: string;
  logX?: boolean;
  logY?: boolean;
  series: Series[];
  /** Horizontal reference lines. */
  refs?: { y: number; label: string }[];
  yMin?: number;
  yMax?: number;
}

const fmt = (v: number) => (Math.abs(v) >= 1000 ? `${v / 1000}k` : Math.abs(v) >= 1 || v === 0 ? String(+v.toPrecision(3)) : String(+v.toPrecision(2)));

function ticks(lo: number, hi: number, log: boolean): number[] {
  if (log) {
    const out: number[] = [];
    for (let e = Math.floor(Math.log10(lo)); e <= Math.ceil(Math.log10(hi)); e++) for (const m of [1, 2, 5]) {
      const v = m * 10 ** e;
      if (v >= lo * 0.999 && v <= hi * 1.001) out.push(v);
    }
    return out;
  }
  const span = hi - lo || 1;
  const step = 10 ** Math.floor(Math.log10(span / 5));
  const nice = [1, 2, 5, 10].map((m) => m * step).find((st) => span / st <= 6) ?? step * 10;
  const out: number[] = [];
  for (let v = Math.ceil(lo / nice) * nice; v <= hi + 1e-9; v += nice) out.push(+v.toPrecision(6));
  return out;
}

function plot(o: PlotOptions): HTMLElement {
  const W = 540, H = 300, L = 58, R = 175, T = 12, B = 42;
  const all = o.series.flatMap((x) => x.points).filter(([x, y]) => Number.isFinite(x) && Number.isFinite(y) && (!o.logX || x > 0) && (!o.logY || y > 0));
  const fig = h('figure');
  fig.append(h('figcaption', o.title));
  if (!all.length) {
    fig.append(h('p', 'no data', 'missing'));
    return fig;
  }
  let [x0, x1] = [Math.min(...all.map((p) => p[0])), Math.max(...all.map((p) => p[0]))];
  let [y0, y1] = [o.yMin ?? Math.min(...all.map((p) => p[1])), o.yMax ?? Math.max(...all.map((p) => p[1]))];
  for (const r of o.refs ?? []) (y0 = Math.min(y0, r.y)), (y1 = Math.max(y1, r.y));
  if (!o.logY && o.yMin === undefined) y0 = Math.min(0, y0);
  if (x0 === x1) (x0 -= 1), (x1 += 1);
  if (y0 === y1) y1 = y0 + 1;
  if (o.logY) (y0 = 10 ** Math.floor(Math.log10(y0))), (y1 = 10 ** Math.ceil(Math.log10(y1)));
  const tx = (x: number) => L + ((o.logX ? Math.log10(x / x0) / Math.log10(x1 / x0) : (x - x0) / (x1 - x0)) * (W - L - R));
  const ty = (y: number) => H - B - ((o.logY ? Math.log10(y / y0) / Math.log10(y1 / y0) : (y - y0) / (y1 - y0)) * (H - T - B));
  const svg = s('svg', { viewBox: `0 0 ${W} ${H}`, role: 'img', 'aria-label': o.title });
  svg.append(s('rect', { x: L, y: T, width: W - L - R, height: H - T - B, fill: '#fafafa', stroke: '#ccc' }));
  for (const v of ticks(y0, y1, !!o.logY)) {
    svg.append(s('line', { x1: L, x2: W - R, y1: ty(v), y2: ty(v), stroke: '#e6e6e6' }));
    svg.append(s('text', { x: L - 5, y: ty(v) + 4, 'text-anchor': 'end', 'font-size': 10, fill: '#555' }, fmt(v)));
  }
  const xt = o.logX ? ticks(x0, x1, true) : ticks(x0, x1, false);
  for (const v of xt) {
    svg.append(s('line', { x1: tx(v), x2: tx(v), y1: T, y2: H - B, stroke: '#eee' }));
    svg.append(s('text', { x: tx(v), y: H - B + 14, 'text-anchor': 'middle', 'font-size': 10, fill: '#555' }, fmt(v)));
  }
  svg.append(s('text', { x: (L + W - R) / 2, y: H - 8, 'text-anchor': 'middle', 'font-size': 11, fill: '#333' }, o.xLabel + (o.logX ? ' (log)' : '')));
  svg.append(s('text', { x: 12, y: (T + H - B) / 2, 'text-anchor': 'middle', 'font-size': 11, fill: '#333', transform: `rotate(-90 12 ${(T + H - B) / 2})` }, o.yLabel + (o.logY ? ' (log)' : '')));
  for (const r of o.refs ?? []) {
    svg.append(s('line', { x1: L, x2: W - R, y1: ty(r.y), y2: ty(r.y), stroke: '#c0392b', 'stroke-dasharray': '5 4' }));
    svg.append(s('text', { x: L + 4, y: ty(r.y) - 4, 'font-size': 10, fill: '#c0392b' }, r.label));
  }
  o.series.forEach((ser, i) => {
    const c = COLORS[i % COLORS.length];
    const pts = ser.points.filter(([x, y]) => Number.isFinite(x) && Number.isFinite(y) && (!o.logX || x > 0) && (!o.logY || y > 0));
    if (pts.length) svg.append(s('polyline', { points: pts.map(([x, y]) => `${tx(x).toFixed(1)},${ty(y).toFixed(1)}`).join(' '), fill: 'none', stroke: c, 'stroke-width': 2, ...(ser.dash ? { 'stroke-dasharray': '6 3' } : {}) }));
    for (const [x, y] of pts) svg.append(s('circle', { cx: tx(x), cy: ty(y), r: 2.8, fill: c }));
    const ly = T + 10 + i * 16;
    svg.append(s('line', { x1: W - R + 8, x2: W - R + 26, y1: ly, y2: ly, stroke: c, 'stroke-width': 2, ...(ser.dash ? { 'stroke-dasharray': '6 3' } : {}) }));
    svg.append(s('text', { x: W - R + 30, y: ly + 4, 'font-size': 10.5, fill: '#333' }, ser.name));
  });
  fig.append(chartBox(svg, o.title));
  return fig;
}

/** Grouped bar chart: one group per category, one bar per series (log y). */
function bars(title: string, yLabel: string, categories: string[], series: { name: string; values: (number | null)[] }[]): HTMLElement {
  const W = 1040, H = 320, L = 58, R = 175, T = 12, B = 42;
  const fig = h('figure');
  fig.append(h('figcaption', title));
  const vals = series.flatMap((x) => x.values).filter((v): v is number => v != null && v > 0);
  if (!vals.length) return fig;
  const y0 = 10 ** Math.floor(Math.log10(Math.min(...vals)));
  const y1 = 10 ** Math.ceil(Math.log10(Math.max(...vals)));
  const ty = (y: number) => H - B - (Math.log10(y / y0) / Math.log10(y1 / y0)) * (H - T - B);
  const svg = s('svg', { viewBox: `0 0 ${W} ${H}`, role: 'img', 'aria-label': title });
  svg.append(s('rect', { x: L, y: T, width: W - L - R, height: H - T - B, fill: '#fafafa', stroke: '#ccc' }));
  for (const v of ticks(y0, y1, true)) {
    svg.append(s('line', { x1: L, x2: W - R, y1: ty(v), y2: ty(v), stroke: '#e6e6e6' }));
    svg.append(s('text', { x: L - 5, y: ty(v) + 4, 'text-anchor': 'end', 'font-size': 10, fill: '#555' }, fmt(v)));
  }
  svg.append(s('text', { x: 12, y: (T + H - B) / 2, 'text-anchor': 'middle', 'font-size': 11, fill: '#333', transform: `rotate(-90 12 ${(T + H - B) / 2})` }, `${yLabel} (log)`));
  const gw = (W - L - R) / categories.length;
  const bw = (gw * 0.8) / series.length;
  categories.forEach((cat, ci) => {
    svg.append(s('text', { x: L + gw * (ci + 0.5), y: H - B + 16, 'text-anchor': 'middle', 'font-size': 11, fill: '#333' }, cat));
    series.forEach((ser, si) => {
      const v = ser.values[ci];
      if (v == null || !(v > 0)) return;
      const x = L + gw * ci + gw * 0.1 + si * bw;
      const rect = s('rect', { x, y: ty(v), width: Math.max(1, bw - 1), height: H - B - ty(v), fill: COLORS[si % COLORS.length] });
      rect.append(s('title', {}, `${cat} · ${ser.name}: ${v} ms`));
      svg.append(rect);
    });
  });
  series.forEach((ser, i) => {
    const ly = T + 10 + i * 16;
    svg.append(s('rect', { x: W - R + 8, y: ly - 6, width: 14, height: 10, fill: COLORS[i % COLORS.length] }));
    svg.append(s('text', { x: W - R + 28, y: ly + 3, 'font-size': 10.5, fill: '#333' }, ser.name));
  });
  fig.append(chartBox(svg, title));
  return fig;
}

/**
 * A chart in a box that scrolls sideways on a phone, where the chart keeps a width its 10-unit labels can be read at
 * (drawn 330 px wide they were 6 px tall), reachable by keyboard.
 */
function chartBox(svg: SVGElement, title: string): HTMLElement {
  const box = h('div', undefined, 'chart-scroll');
  box.tabIndex = 0;
  box.setAttribute('role', 'region');
  box.setAttribute('aria-label', `chart: ${title}`);
  // On a phone (report.html's media query) at least 0.9 of its drawing width: its labels then stay 9 px or more.
  const width = Number(svg.getAttribute('viewBox')?.split(' ')[2]);
  if (width > 0) box.style.setProperty('--chart-min-width', `${Math.round(0.9 * width)}px`);
  box.append(svg);
  return box;
}

/** A table in a box that scrolls sideways when the page is narrower than the table (a phone), reachable by keyboard. */
function table(head: string[], rows: string[][]): HTMLElement {
  const box = h('div', undefined, 'table-scroll');
  box.tabIndex = 0;
  box.setAttribute('role', 'region');
  box.setAttribute('aria-label', `table: ${head[0]}, ${head.slice(1, 3).join(', ')}…`);
  const t = h('table');
  box.append(t);
  const tr = h('tr');
  for (const c of head) tr.append(h('th', c));
  t.append(tr);
  for (const r of rows) {
    const row = h('tr');
    for (const c of r) row.append(h('td', c));
    t.append(row);
  }
  return box;
}

async function fetchText(path: string): Promise<string | null> {
  const r = await fetch(path, { cache: 'no-store' });
  return r.ok ? r.text() : null;
}

const pct = (v: number | null | undefined) => (v == null || !Number.isFinite(v) ? '–' : `${(v * 100).toFixed(0)}%`);
const closing: string[] = [];

// ---- experiment 1 ---------------------------------------------------------------------------------------------

interface E1Row { objects: number; narrowphase: string; broadphase: string; msPerStep: number; detectMsPerStep: number; testsPerStep: number; contactsPerStep: number; hitRate: number }
async function experiment1(): Promise<void> {
  const box = document.getElementById('e1')!;
  const text = await fetchText('../bench/results/experiment1.json');
  if (!text) return void box.append(h('p', 'bench/results/experiment1.json is missing: run the command above.', 'missing'));
  const { summary, rows } = JSON.parse(text) as { summary: Record<string, unknown> & { gridGainAt100: { sat: number; gjk: number }; gridGainAt100Total?: { sat: number; gjk: number }; loadavgBefore?: number[]; loadavgAfter?: number[] }; rows: E1Row[] };
  const combos = [['sat', 'grid'], ['sat', 'brute'], ['gjk', 'grid'], ['gjk', 'brute']] as const;
  const series = (key: keyof E1Row) => combos.map(([np, bp]) => ({ name: `${np.toUpperCase()} + ${bp}`, dash: bp === 'brute', points: rows.filter((r) => r.narrowphase === np && r.broadphase === bp).map((r) => [r.objects, r[key] as number] as [number, number]) }));
  const sizes = [...new Set(rows.map((r) => r.objects))];
  const gain = (np: string, key: 'detectMsPerStep' | 'msPerStep') => sizes.map((n) => {
    const g = rows.find((r) => r.objects === n && r.narrowphase === np && r.broadphase === 'grid')?.[key];
    const b = rows.find((r) => r.objects === n && r.narrowphase === np && r.broadphase === 'brute')?.[key];
    return [n, g != null && b ? 100 * (1 - g / b) : NaN] as [number, number];
  });
  const g = summary.gridGainAt100;
  const p = h('p', `Grid vs brute force at 100 objects: ${pct(g.sat)} less collision-detection time with SAT, ${pct(g.gjk)} with GJK + EPA` + (summary.gridGainAt100Total ? ` (whole step: ${pct(summary.gridGainAt100Total.sat)} and ${pct(summary.gridGainAt100Total.gjk)})` : '') + '. The seed claims up to 65%.', 'summary');
  const meta = h('p', `Measured ${String(summary.date).slice(0, 16).replace('T', ' ')} UTC, Node ${summary.node}, ${summary.runs} runs per point${summary.smallSizeRuns ? ` (${summary.smallSizeRuns} up to 200 objects)` : ''}, medians${summary.warmup ? ', after a discarded warm-up pass' : ''}${summary.loadavgBefore ? `; machine load ${summary.loadavgBefore[0].toFixed(1)} → ${summary.loadavgAfter?.[0].toFixed(1)} on ${summary.cpus} shared cores` : ''}. Convex polygons of 3–8 vertices moving at up to 5 units/s, no gravity, about 15% of the box covered.`, 'meta');
  const plots = h('div', undefined, 'plots');
  plots.append(
    plot({ title: 'Time per step', xLabel: 'moving polygons', yLabel: 'ms per step', logX: true, logY: true, series: series('msPerStep') }),
    plot({ title: 'Collision detection per step (broad + narrow phase)', xLabel: 'moving polygons', yLabel: 'ms per step', logX: true, logY: true, series: series('detectMsPerStep') }),
    plot({ title: 'Grid gain over brute force (detection time)', xLabel: 'moving polygons', yLabel: '% less time with the grid', logX: true, series: [{ name: 'SAT', points: gain('sat', 'detectMsPerStep') }, { name: 'GJK + EPA', points: gain('gjk', 'detectMsPerStep') }], refs: [{ y: 65, label: "seed's claim: up to 65%" }, { y: 0, label: '' }] }),
    plot({ title: 'Narrow-phase tests and contacts per step', xLabel: 'moving polygons', yLabel: 'tests per step', logX: true, logY: true, series: [{ name: 'tests (SAT, grid)', points: rows.filter((r) => r.narrowphase === 'sat' && r.broadphase === 'grid').map((r) => [r.objects, r.testsPerStep]) }, { name: 'contacts (SAT, grid)', points: rows.filter((r) => r.narrowphase === 'sat' && r.broadphase === 'grid').map((r) => [r.objects, r.contactsPerStep]) }] }),
  );
  const hit = rows.filter((r) => r.testsPerStep > 0);
  const meanHit = hit.reduce((a, r) => a + r.hitRate, 0) / (hit.length || 1);
  box.append(p, meta, plots, h('p', `Hit rate (tests that found a real contact): ${pct(Math.min(...hit.map((r) => r.hitRate)))}–${pct(Math.max(...hit.map((r) => r.hitRate)))}, mean ${pct(meanHit)}; both broad phases hand the narrow phase the same pairs (same tests per step), so the grid's gain is all in finding the pairs.`, 'meta'));
  const big = Math.max(...rows.filter((r) => r.broadphase === 'brute').map((r) => r.objects));
  const at = (n: number, np: string, bp: string) => rows.find((r) => r.objects === n && r.narrowphase === np && r.broadphase === bp);
  const gb = at(big, 'sat', 'grid'), bb = at(big, 'sat', 'brute');
  closing.push(`Experiment 1: at 100 objects the grid saves ${pct(g.sat)} (SAT) and ${pct(g.gjk)} (GJK) of detection time against the seed's "up to 65%"` + (gb && bb ? `; at ${big} objects it saves ${pct(1 - gb.detectMsPerStep / bb.detectMsPerStep)} (SAT: ${gb.detectMsPerStep.toFixed(2)} vs ${bb.detectMsPerStep.toFixed(2)} ms)` : '') + (() => {
    const top = Math.max(...rows.map((r) => r.objects));
    const t = at(top, 'sat', 'grid');
    return top > big && t ? `; with the grid alone it goes on to ${top} objects at ${t.msPerStep.toFixed(1)} ms per step (SAT)` : '';
  })() + '. Below a few hundred objects the timings are fractions of a millisecond and move by a few points from run to run on the shared machine.');
}

// ---- experiment 2 ---------------------------------------------------------------------------------------------

interface E2Row { bodies: number; configuration: string; transport: string; mainMsPerFrame: number; scriptMsPerFrame: number; fps: number; frameMs: number; jitterMs: number; p95FrameMs: number; longTasks: number; stepsPerSecond: number }
async function experiment2(): Promise<void> {
  const box = document.getElementById('e2')!;
  const text = await fetchText('../bench/results/experiment2.json');
  if (!text) return void box.append(h('p', 'bench/results/experiment2.json is missing: run the command above.', 'missing'));
  const { summary, rows } = JSON.parse(text) as { summary: Record<string, unknown> & { loadavgBefore: number[]; loadavgAfter: number[] }; rows: E2Row[] };
  const configs = [...new Set(rows.map((r) => r.configuration))];
  const series = (key: keyof E2Row) => configs.map((c) => ({ name: c, points: rows.filter((r) => r.configuration === c).map((r) => [r.bodies, r[key] as number] as [number, number]) }));
  box.append(h('p', `Measured ${String(summary.date).slice(0, 16).replace('T', ' ')} UTC in headless chromium (software rendering, --disable-gpu), ${summary.runs} page loads per point (median), ${summary.seconds} s measured after 1 s of warm-up; machine load ${summary.loadavgBefore[0].toFixed(1)} → ${summary.loadavgAfter[0].toFixed(1)} on ${summary.cpus} shared cores. Main-thread time is the renderer's TaskDuration from the DevTools protocol divided by the frames drawn; the scene is a 960 × 540 canvas of falling boxes and circles.`, 'meta'));
  const plots = h('div', undefined, 'plots');
  plots.append(
    plot({ title: 'Main-thread time per frame: all tasks (solid), script only (dashed)', xLabel: 'bodies', yLabel: 'ms per frame', logX: true, logY: true, series: [...series('mainMsPerFrame'), ...series('scriptMsPerFrame').map((x) => ({ ...x, name: `${x.name.replace('worker, ', '')} (script)`, dash: true }))] }),
    plot({ title: 'Frames per second', xLabel: 'bodies', yLabel: 'fps', logX: true, series: series('fps'), yMin: 0 }),
    plot({ title: 'Frame-time jitter (standard deviation of frame intervals)', xLabel: 'bodies', yLabel: 'ms', logX: true, series: series('jitterMs') }),
    plot({ title: 'Long tasks (> 50 ms) in the measured window', xLabel: 'bodies', yLabel: 'count', logX: true, series: series('longTasks') }),
  );
  box.append(plots, table(['bodies', 'configuration', 'transport', 'main ms/frame', 'script ms/frame', 'fps', 'jitter ms', 'p95 frame ms', 'long tasks', 'steps/s'], rows.map((r) => [String(r.bodies), r.configuration, r.transport, r.mainMsPerFrame.toFixed(2), r.scriptMsPerFrame.toFixed(2), r.fps.toFixed(1), r.jitterMs.toFixed(2), r.p95FrameMs.toFixed(1), String(r.longTasks), r.stepsPerSecond.toFixed(0)])));
  const big = Math.max(...rows.map((r) => r.bodies));
  const at = (c: string) => rows.find((r) => r.bodies === big && r.configuration === c);
  const parts = configs.map((c) => at(c)).filter(Boolean).map((r) => `${r!.configuration} ${r!.scriptMsPerFrame.toFixed(1)} ms of script and ${r!.mainMsPerFrame.toFixed(1)} ms of main-thread tasks per frame at ${r!.fps.toFixed(0)} fps, ${r!.longTasks} long tasks`);
  const mid = rows.filter((r) => r.bodies === 500);
  const mainMid = mid.find((r) => r.transport === 'direct');
  const workerMid = mid.filter((r) => r.transport !== 'direct');
  closing.push(
    `Experiment 2: at ${big} bodies, ${parts.join('; ')}.` +
      (mainMid && workerMid.length ? ` At 500 bodies the worker takes the main thread's script time from ${mainMid.scriptMsPerFrame.toFixed(1)} ms to ${workerMid.map((r) => r.scriptMsPerFrame.toFixed(1)).join(' / ')} ms per frame (shared / transferred); the main-thread time that stays is rendering outside script (paint, canvas rasterization, compositing: the DevTools protocol counts it in tasks, not in script), which headless software rendering makes expensive, and on this overloaded 2-core machine the worker competes with it for CPU, so frame rate and jitter gain little.` : ''),
  );
}

// ---- experiment 3 ---------------------------------------------------------------------------------------------

/** Markdown tables under a "## heading" of peers.md. */
function mdTable(md: string, heading: string): string[][] | null {
  const start = md.indexOf(`## ${heading}`);
  if (start < 0) return null;
  const lines = md.slice(start).split('\n').slice(1);
  const rows: string[][] = [];
  for (const line of lines) {
    if (line.startsWith('## ')) break;
    if (!line.startsWith('|')) {
      if (rows.length) break;
      continue;
    }
    if (/^\|\s*-/.test(line)) continue;
    // Cells split at unescaped pipes: a label may hold |d − L|, written \|d − L\| in the markdown.
    rows.push(line.slice(1, -1).split(/(?<!\\)\|/).map((c) => c.trim().replace(/\\\|/g, '|').replace(/\*\*/g, '')));
  }
  return rows.length ? rows : null;
}

async function experiment3(): Promise<void> {
  const box = document.getElementById('e3')!;
  let file = 'peers.md';
  let md = await fetchText('../bench/results/peers.md');
  if (!md) (file = 'peers-quick.md'), (md = await fetchText('../bench/results/peers-quick.md'));
  if (!md) {
    box.append(h('p', 'No bench/results/peers.md yet (the full run takes a while): run one of the commands above.', 'missing'));
    closing.push('Experiment 3: no results file yet.');
    return;
  }
  const gen = md.split('\n').find((l) => l.startsWith('Generated by')) ?? '';
  const load = md.split('\n').find((l) => l.startsWith('Machine load')) ?? '';
  box.append(h('p', `From bench/results/${file}. ${gen.replace(/`/g, '')} ${(load.match(/^.*?cores\./) ?? [load])[0]}`, 'meta'));
  const time = mdTable(md, 'Milliseconds per step');
  if (time) {
    const head = time[0];
    const engineCols = head.map((c, i) => [c, i] as const).filter(([c, i]) => i > 0 && !c.includes('÷'));
    const scenes = time.slice(1).map((r) => r[0]);
    box.append(
      bars('Milliseconds per step, per scene and engine (lower is better)', 'ms per step', scenes.map((sc) => sc.split(' ')[0]), engineCols.map(([name, i]) => ({ name, values: time.slice(1).map((r) => (Number.isFinite(parseFloat(r[i])) ? parseFloat(r[i]) : null)) }))),
      table(head, time.slice(1)),
    );
    const ratioCol = head.findIndex((c) => c.startsWith('ours ÷'));
    if (ratioCol > 0) closing.push(`Experiment 3 (ours ÷ fastest peer, ms per step): ${time.slice(1).map((r) => `${r[0].split(' ')[0]} ${r[ratioCol]}`).join('; ')}.`);
  }
  const quality = mdTable(md, 'Quality');
  if (quality) box.append(h('h3', 'Quality'), table(quality[0], quality.slice(1)));
}

// ---- experiment 4 ---------------------------------------------------------------------------------------------

interface KernelRow { scene: string; title: string; particles: number; links: number; jsMs: number; wasmMs: number; wallJsMs: number; wallWasmMs: number; strainJs: string; strainWasm: string }
async function experiment4(): Promise<void> {
  const box = document.getElementById('e4')!;
  const text = await fetchText('../bench/results/kernel.json');
  if (!text) return void box.append(h('p', 'bench/results/kernel.json is missing: run the command above.', 'missing'));
  const { summary, rows } = JSON.parse(text) as { summary: { date: string; runs: number; fresh?: boolean; node: string; cpus: number; load: number[]; wasmBytes: number; wasmGzip: number }; rows: KernelRow[] };
  const how = summary.fresh ? 'each run in a fresh process' : 'in one process';
  box.append(h('p', `Measured ${summary.date.slice(0, 16).replace('T', ' ')} UTC in Node ${summary.node}, ${summary.runs} runs per kernel alternating, ${how} (median CPU ms per step), sleeping off; machine load ${Math.min(...summary.load).toFixed(1)}–${Math.max(...summary.load).toFixed(1)} on ${summary.cpus} shared cores. The kernel is ${summary.wasmBytes} bytes of WebAssembly (${summary.wasmGzip} gzip).`, 'meta'));
  const bySize = [...rows].sort((a, b) => a.particles - b.particles);
  box.append(
    bars('Step time by scene size: JS solver vs WebAssembly SIMD kernel (lower is better)', 'CPU ms per step', bySize.map((r) => `${r.scene} (${r.particles.toLocaleString('en')})`), [
      { name: 'JS kernel', values: bySize.map((r) => r.jsMs) },
      { name: 'WebAssembly kernel', values: bySize.map((r) => r.wasmMs) },
    ]),
    table(['scene', 'particles', 'links', 'JS ms/step', 'WASM ms/step', 'WASM ÷ JS', 'max strain JS', 'WASM'], bySize.map((r) => [r.title, String(r.particles), String(r.links), r.jsMs.toFixed(3), r.wasmMs.toFixed(3), (r.wasmMs / r.jsMs).toFixed(2), r.strainJs, r.strainWasm])),
  );
  closing.push(`Experiment 4 (WebAssembly ÷ JS kernel, CPU ms per step): ${bySize.map((r) => `${r.scene} ${(r.wasmMs / r.jsMs).toFixed(2)} (${r.jsMs.toFixed(2)} → ${r.wasmMs.toFixed(2)} ms)`).join('; ')}.`);
}

await Promise.all([experiment1(), experiment2(), experiment3(), experiment4()]);
const c = document.getElementById('closing')!;
c.replaceChildren(h('strong', 'Closing note. '), ...closing.map((t) => h('p', t)));
export {};
