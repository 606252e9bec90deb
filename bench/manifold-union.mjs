// The reference for bench/compare-manifold: Manifold's batch union of the
// segments of one `lsolid skeleton --json` (millimetres), each segment the
// convex hull of a sphere at either end, as an OpenSCAD or Manifold user
// would model a tapered branch. Leaves are left out.
//
//   node bench/manifold-union.mjs MANIFOLD_JS SKELETON_JSON TOLERANCE_MM
//
// Prints one JSON object: the time to make the hulls and the time of the
// union (forced: Manifold evaluates lazily), the union's triangles, volume
// and pieces.
import fs from 'node:fs';
import {pathToFileURL} from 'node:url';

const [moduleFile, skeletonFile, toleranceText] = process.argv.slice(2);
const Module = (await import(pathToFileURL(moduleFile).href)).default;
const wasm = await Module();
wasm.setup();
const {Manifold} = wasm;

const skeleton = JSON.parse(fs.readFileSync(skeletonFile, 'utf8'));
if (skeleton.units !== 'mm') {
  throw new Error('the skeleton must be in millimetres (give lsolid skeleton --scale)');
}
const tolerance = Number(toleranceText);

// As many sides as keep the chord within the tolerance, the rule lsolid's
// tubes follow, in multiples of four as Manifold rounds them.
function sides(radius) {
  if (radius <= tolerance) return 4;
  const n = Math.ceil(Math.PI / Math.acos(1 - tolerance / radius));
  return Math.max(4, 4 * Math.ceil(n / 4));
}

const hullStart = performance.now();
const hulls = [];
for (const s of skeleton.segments) {
  const a = Manifold.sphere(s.r0, sides(s.r0)).translate(s.p0);
  const b = Manifold.sphere(s.r1, sides(s.r1)).translate(s.p1);
  hulls.push(Manifold.hull([a, b]));
  a.delete();
  b.delete();
}
const hullSeconds = (performance.now() - hullStart) / 1000;

const unionStart = performance.now();
const union = Manifold.union(hulls);
const triangles = union.numTri();
const unionSeconds = (performance.now() - unionStart) / 1000;

const pieces = union.decompose();
console.log(JSON.stringify({
  segments: skeleton.segments.length,
  hull_seconds: hullSeconds,
  union_seconds: unionSeconds,
  triangles,
  volume_mm3: union.volume(),
  pieces: pieces.filter((p) => p.volume() > 1e-9).length,
  status: String(union.status().value ?? union.status()),
}));
