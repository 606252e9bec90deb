// The anchor of bench/compare-manifold: Manifold's batch union of lsolid's
// own parts, as `lsolid FILE --no-union -o parts.off` writes them (the
// overlapping closed parts in one OFF file; each connected set of triangles
// is one part, given to Manifold as one Manifold).
//
//   node bench/manifold-parts.mjs MANIFOLD_JS PARTS_OFF
//
// Prints one JSON object: the parts, the time to make them Manifolds, the
// time of the union (forced: Manifold evaluates lazily), the union's
// triangles, volume and pieces.
import fs from 'node:fs';
import {pathToFileURL} from 'node:url';

const [moduleFile, offFile] = process.argv.slice(2);
const Module = (await import(pathToFileURL(moduleFile).href)).default;
const wasm = await Module();
wasm.setup();
const {Manifold, Mesh} = wasm;

const words = fs.readFileSync(offFile, 'utf8')
                  .split('\n')
                  .filter((line) => !line.startsWith('#'))
                  .join(' ')
                  .split(/\s+/)
                  .filter((w) => w.length > 0);
if (words[0] !== 'OFF') throw new Error(`${offFile} is not an OFF file`);
const vertexCount = Number(words[1]);
const faceCount = Number(words[2]);
let at = 4;
const positions = new Float64Array(3 * vertexCount);
for (let i = 0; i < 3 * vertexCount; ++i) positions[i] = Number(words[at++]);
const triangles = new Uint32Array(3 * faceCount);
for (let f = 0; f < faceCount; ++f) {
  if (words[at++] !== '3') throw new Error('only triangles are read');
  for (let k = 0; k < 3; ++k) triangles[3 * f + k] = Number(words[at++]);
}

// Parts: triangles joined through the vertices they share.
const parent = Int32Array.from({length: vertexCount}, (_, i) => i);
const find = (x) => {
  while (parent[x] !== x) x = parent[x] = parent[parent[x]];
  return x;
};
for (let f = 0; f < faceCount; ++f) {
  const a = find(triangles[3 * f]);
  for (let k = 1; k < 3; ++k) {
    const b = find(triangles[3 * f + k]);
    if (a !== b) parent[b] = a;
  }
}
const parts = new Map();
for (let f = 0; f < faceCount; ++f) {
  const root = find(triangles[3 * f]);
  if (!parts.has(root)) parts.set(root, []);
  parts.get(root).push(f);
}

const makeStart = performance.now();
const manifolds = [];
for (const faces of parts.values()) {
  const local = new Map();
  const props = [];
  const tris = new Uint32Array(3 * faces.length);
  faces.forEach((f, i) => {
    for (let k = 0; k < 3; ++k) {
      const v = triangles[3 * f + k];
      if (!local.has(v)) {
        local.set(v, local.size);
        props.push(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
      }
      tris[3 * i + k] = local.get(v);
    }
  });
  const mesh = new Mesh({numProp: 3, vertProperties: new Float32Array(props),
                         triVerts: tris});
  mesh.merge();
  manifolds.push(new Manifold(mesh));
}
const makeSeconds = (performance.now() - makeStart) / 1000;

const unionStart = performance.now();
const union = Manifold.union(manifolds);
const triangleCount = union.numTri();
const unionSeconds = (performance.now() - unionStart) / 1000;

const pieces = union.decompose();
console.log(JSON.stringify({
  parts: manifolds.length,
  make_seconds: makeSeconds,
  union_seconds: unionSeconds,
  triangles: triangleCount,
  volume_mm3: union.volume(),
  pieces: pieces.filter((p) => p.volume() > 1e-9).length,
  status: String(union.status().value ?? union.status()),
}));
