// Narrow-phase benchmark (issue 3; first half of the seed's experiment 1): ns per call of SAT, boolean GJK and
// GJK + EPA over random convex polygons of 3 to 8 vertices, overlapping and separated pairs timed apart, with hit
// counts; the `sat` npm package (SAT.js) on the same pairs as an external reference: same answers, speed ratio.
// Usage: node bench/collision.mjs [--runs 9] [--pairs 1000]
import SAT from 'sat';
import { importTs } from '../scripts/build-engine-for-node.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? Number(process.argv[i + 1]) : fallback;
};
const runs = arg('--runs', 9);
const pairCount = arg('--pairs', 1000);
const C = await importTs('src/engine/collision/index.ts');

// ---- Random convex polygons (fixed seed): points on a circle at sorted random angles, stretched and rotated.
let seed = 12345;
const rand = () => {
  seed = (seed + 0x6d2b79f5) >>> 0;
  let t = seed;
  t = Math.imul(t ^ (t >>> 15), t | 1);
  t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
};

function randomPolygon(cx, cy, size) {
  const n = 3 + Math.floor(rand() * 6);
  let angles;
  do angles = Array.from({ length: n }, () => rand() * 2 * Math.PI).sort((a, b) => a - b);
  while (angles.some((a, k) => (k + 1 < n ? angles[k + 1] : angles[0] + 2 * Math.PI) - a < 0.15 || (k + 1 < n ? angles[k + 1] : angles[0] + 2 * Math.PI) - a > Math.PI - 0.1));
  const rot = rand() * 2 * Math.PI;
  const stretch = 0.4 + 0.6 * rand();
  return angles.map((a) => {
    const u = size * Math.cos(a);
    const v = size * stretch * Math.sin(a);
    return { x: cx + u * Math.cos(rot) - v * Math.sin(rot), y: cy + u * Math.sin(rot) + v * Math.cos(rot) };
  });
}

// Pairs placed so that about half overlap; then split by the true answer. Each library's shapes are built in a pass
// of their own, so that neither's objects are scattered among the other's (a cache effect, not an algorithm one).
const raw = [];
for (let k = 0; k < pairCount; k++) {
  const pa = randomPolygon(0, 0, 0.5 + rand());
  const ang = rand() * 2 * Math.PI;
  const d = rand() * 2.4;
  raw.push([pa, randomPolygon(d * Math.cos(ang), d * Math.sin(ang), 0.5 + rand())]);
}
const ours = raw.map(([pa, pb]) => ({ a: C.polygon(pa), b: C.polygon(pb) }));
// SAT.js: polygons at the origin with absolute points (its `pos` offsets are not needed for a like-for-like test).
const theirs = raw.map(([pa, pb]) => ({
  sa: new SAT.Polygon(new SAT.Vector(0, 0), pa.map((p) => new SAT.Vector(p.x, p.y))),
  sb: new SAT.Polygon(new SAT.Vector(0, 0), pb.map((p) => new SAT.Vector(p.x, p.y))),
}));
const pairs = raw.map(([pa, pb], k) => ({ ...ours[k], ...theirs[k], vertices: pa.length + pb.length }));
const pen = new C.Penetration();
const overlapping = pairs.filter((p) => C.sat(p.a, p.b, pen));
const separated = pairs.filter((p) => !C.sat(p.a, p.b, pen));

// ---- Same answers: ours against each other and against SAT.js.
const response = new SAT.Response();
const epaOut = new C.Penetration();
let disagreeHit = 0;
let disagreeDepth = 0;
let disagreeNormal = 0;
let disagreeInternal = 0;
let worstDepth = 0;
for (const p of pairs) {
  const ours = C.sat(p.a, p.b, pen);
  response.clear();
  const theirs = SAT.testPolygonPolygon(p.sa, p.sb, response);
  if (ours !== C.gjkIntersect(p.a, p.b) || ours !== C.gjkEpa(p.a, p.b, epaOut)) disagreeInternal++;
  if (ours && Math.abs(epaOut.depth - pen.depth) > 1e-9) disagreeInternal++;
  if (ours !== theirs) {
    disagreeHit++;
    continue;
  }
  if (!ours) continue;
  const dd = Math.abs(response.overlap - pen.depth);
  worstDepth = Math.max(worstDepth, dd);
  if (dd > 1e-9) disagreeDepth++;
  else if (response.overlapN.x * pen.normalX + response.overlapN.y * pen.normalY < 1 - 1e-9) disagreeNormal++;
}

// ---- Timing: each case gets its own loop (compiled from source, so every call site stays monomorphic and the
// harness costs the same for all), runs over its pair list `reps` times; the median of `runs` runs is reported.
const cp = new C.ClosestPoints();
const man = new C.Manifold();
const cases = {
  'SAT (MTV)': 'sat(p.a, p.b, pen) ? pen.depth : 0',
  'boolean GJK': 'gjkIntersect(p.a, p.b) ? 1 : 0',
  'GJK + EPA': 'gjkEpa(p.a, p.b, epaOut) ? epaOut.depth : 0',
  'manifold (clipping)': 'polygonManifold(p.a, p.b, man) ? man.count : 0',
  'GJK distance': 'gjkDistance(p.a, p.b, cp)',
  'SAT.js with Response': '(response.clear(), testPolygonPolygon(p.sa, p.sb, response)) ? response.overlap : 0',
  'SAT.js boolean': 'testPolygonPolygon(p.sa, p.sb) ? 1 : 0',
};
const env = { ...C, testPolygonPolygon: SAT.testPolygonPolygon, pen, epaOut, man, cp, response };
function timer(expr) {
  // eslint-disable-next-line no-new-func
  return new Function('env', `const { ${Object.keys(env).join(', ')} } = env;
    return function run(list, reps) {
      let hits = 0;
      let sink = 0;
      const t0 = process.hrtime.bigint();
      for (let r = 0; r < reps; r++) {
        for (let i = 0; i < list.length; i++) {
          const p = list[i];
          const v = ${expr};
          if (v > 0) hits++;
          sink += v;
        }
      }
      const ns = Number(process.hrtime.bigint() - t0) / (reps * list.length);
      return { ns, hits: hits / reps, sink };
    };`)(env);
}

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const sets = { overlapping, separated, all: pairs };
const results = {};
// Round-robin: every run times every case on every set, so a busy moment on the machine hits all cases alike.
let sink = 0;
const runners = {};
const samples = {};
for (const [name, expr] of Object.entries(cases)) {
  runners[name] = {};
  samples[name] = {};
  for (const [set, list] of Object.entries(sets)) {
    runners[name][set] = timer(expr);
    runners[name][set](list, 20); // warm-up
    samples[name][set] = [];
  }
}
for (let run = 0; run < runs; run++) {
  for (const name of Object.keys(cases)) {
    for (const [set, list] of Object.entries(sets)) {
      const x = runners[name][set](list, Math.max(1, Math.round(100_000 / list.length)));
      sink += x.sink;
      samples[name][set].push(x);
    }
  }
}
for (const name of Object.keys(cases)) {
  results[name] = {};
  for (const set of Object.keys(sets)) {
    const xs = samples[name][set];
    results[name][set] = { ns: median(xs.map((x) => x.ns)), min: Math.min(...xs.map((x) => x.ns)), hits: xs[0].hits };
  }
}

const avgVertices = (pairs.reduce((s, p) => s + p.vertices, 0) / pairs.length / 2).toFixed(2);
console.log(`collision benchmark: ${pairs.length} polygon pairs (3–8 vertices, mean ${avgVertices}), ${overlapping.length} overlapping / ${separated.length} separated; median (and min) of ${runs} round-robin runs; Node ${process.version}, sat ${SAT.Response ? '0.9' : '?'}`);
console.log('');
console.log('| narrow phase | ns/call overlapping | ns/call separated | ns/call all (min) | hits (all) |');
console.log('|---|---|---|---|---|');
for (const [name, r] of Object.entries(results)) {
  console.log(`| ${name} | ${r.overlapping.ns.toFixed(0)} | ${r.separated.ns.toFixed(0)} | ${r.all.ns.toFixed(0)} (${r.all.min.toFixed(0)}) | ${r.all.hits} / ${pairs.length} |`);
}
console.log('');
const ratio = (ours, theirs) => (results[theirs].all.ns / results[ours].all.ns).toFixed(2);
console.log(`speed ratio SAT.js / ours (all pairs): MTV ${ratio('SAT (MTV)', 'SAT.js with Response')}× (SAT.js with Response vs our SAT), ` +
  `boolean ${ratio('boolean GJK', 'SAT.js boolean')}× (SAT.js boolean vs our boolean GJK), ${ratio('SAT (MTV)', 'SAT.js boolean')}× (SAT.js boolean vs our SAT)`);
console.log(`same answers: hit/miss differs on ${disagreeHit} of ${pairs.length} pairs; depth differs (> 1e-9) on ${disagreeDepth}, normal on ${disagreeNormal} of the common hits (worst depth difference ${worstDepth.toExponential(2)}); SAT vs GJK vs GJK+EPA internal disagreements: ${disagreeInternal}`);
if (!Number.isFinite(sink)) console.log('(sink)', sink);
