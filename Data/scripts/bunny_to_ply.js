#!/usr/bin/env node
// Convert the Stanford bunny from the npm package "bunny" (public domain;
// it exports `positions` and `cells`) into a binary little-endian PLY file.
//
// Usage:
//   node bunny_to_ply.js <path/to/node_modules/bunny> <out.ply>
//
// The mesh is written as the package gives it: same points, same order,
// same triangle orientation; nothing is merged, removed or re-oriented.
// Before writing, the script checks the mesh and prints a report:
// index range, unused points, degenerate triangles (repeated index or zero
// area), duplicate triangles, boundary / non-manifold edges and whether the
// orientation is consistent (every interior edge is used once in each
// direction). It exits non-zero only on hard errors (bad indices,
// non-triangles); the report is informational otherwise.
//
// This script is a one-off data-preparation tool; it is not used at build
// or test time.

'use strict';

const fs = require('fs');
const path = require('path');

function usage() {
  process.stderr.write(
    'usage: node bunny_to_ply.js <bunny-package-dir> <out.ply>\n');
  process.exit(2);
}

if (process.argv.length !== 4) usage();
const pkgDir = path.resolve(process.argv[2]);
const outFile = path.resolve(process.argv[3]);

const pkg = JSON.parse(fs.readFileSync(path.join(pkgDir, 'package.json'), 'utf8'));
const bunny = require(pkgDir);
const positions = bunny.positions;
const cells = bunny.cells;

if (!Array.isArray(positions) || !Array.isArray(cells)) {
  throw new Error('package does not export positions/cells arrays');
}

const nPts = positions.length;
const nTri = cells.length;

// ---- checks -------------------------------------------------------------
for (let i = 0; i < nPts; i++) {
  const p = positions[i];
  if (p.length !== 3 || !p.every(Number.isFinite)) {
    throw new Error(`point ${i} is not a finite 3-vector`);
  }
}
const used = new Uint8Array(nPts);
for (let t = 0; t < nTri; t++) {
  const c = cells[t];
  if (c.length !== 3) throw new Error(`cell ${t} is not a triangle`);
  for (const i of c) {
    if (!Number.isInteger(i) || i < 0 || i >= nPts) {
      throw new Error(`cell ${t} has bad index ${i}`);
    }
    used[i] = 1;
  }
}
const unused = nPts - used.reduce((a, b) => a + b, 0);

function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
function cross(a, b) {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}
function norm(a) { return Math.hypot(a[0], a[1], a[2]); }

let degenerateIdx = 0;   // repeated vertex index
let degenerateArea = 0;  // distinct indices but (near) zero area
let minArea = Infinity;
let maxArea = 0;
const triKeys = new Map();
let duplicateTris = 0;
// directed edge "a,b" -> count
const directed = new Map();
for (let t = 0; t < nTri; t++) {
  const [a, b, c] = cells[t];
  if (a === b || b === c || a === c) { degenerateIdx++; continue; }
  const area = 0.5 * norm(cross(sub(positions[b], positions[a]),
                                sub(positions[c], positions[a])));
  minArea = Math.min(minArea, area);
  maxArea = Math.max(maxArea, area);
  // relative threshold: area much smaller than the squared longest edge
  const e2 = Math.max(norm(sub(positions[b], positions[a])),
                      norm(sub(positions[c], positions[b])),
                      norm(sub(positions[a], positions[c]))) ** 2;
  if (area <= 1e-12 * e2 || area === 0) degenerateArea++;
  const key = [a, b, c].sort((x, y) => x - y).join(',');
  if (triKeys.has(key)) duplicateTris++; else triKeys.set(key, t);
  for (const [u, v] of [[a, b], [b, c], [c, a]]) {
    const k = u + ',' + v;
    directed.set(k, (directed.get(k) || 0) + 1);
  }
}

// undirected edge analysis
const undirected = new Map(); // "min,max" -> [count(min->max), count(max->min)]
for (const [k, n] of directed) {
  const [u, v] = k.split(',').map(Number);
  const lo = Math.min(u, v);
  const hi = Math.max(u, v);
  const uk = lo + ',' + hi;
  const e = undirected.get(uk) || [0, 0];
  if (u === lo) e[0] += n; else e[1] += n;
  undirected.set(uk, e);
}
let boundaryEdges = 0;
let interiorEdges = 0;
let nonManifoldEdges = 0;
let inconsistentEdges = 0; // interior edges not used once in each direction
for (const [, [f, r]] of undirected) {
  const n = f + r;
  if (n === 1) boundaryEdges++;
  else if (n === 2) {
    interiorEdges++;
    if (!(f === 1 && r === 1)) inconsistentEdges++;
  } else nonManifoldEdges++;
}

// boundary loops (count of closed loops of boundary edges)
const bnext = new Map();
for (const [k, n] of directed) {
  const [u, v] = k.split(',').map(Number);
  if (!directed.has(v + ',' + u) && n === 1) {
    if (!bnext.has(u)) bnext.set(u, []);
    bnext.get(u).push(v);
  }
}
let boundaryLoops = 0;
{
  const seen = new Set();
  for (const [start] of bnext) {
    for (const first of bnext.get(start)) {
      const k0 = start + ',' + first;
      if (seen.has(k0)) continue;
      boundaryLoops++;
      let u = start;
      let v = first;
      for (;;) {
        seen.add(u + ',' + v);
        const nx = (bnext.get(v) || []).find((w) => !seen.has(v + ',' + w));
        if (nx === undefined) break;
        u = v;
        v = nx;
      }
    }
  }
}

const lo = [Infinity, Infinity, Infinity];
const hi = [-Infinity, -Infinity, -Infinity];
for (const p of positions) {
  for (let k = 0; k < 3; k++) {
    lo[k] = Math.min(lo[k], p[k]);
    hi[k] = Math.max(hi[k], p[k]);
  }
}

// signed volume (divergence theorem); > 0 means normals point outward for a
// closed, consistently oriented mesh
let signedVolume = 0;
for (const [a, b, c] of cells) {
  const pa = positions[a];
  const bc = cross(positions[b], positions[c]);
  signedVolume += (pa[0] * bc[0] + pa[1] * bc[1] + pa[2] * bc[2]) / 6;
}

const consistent = inconsistentEdges === 0 && nonManifoldEdges === 0;
const report = [
  `package: ${pkg.name} ${pkg.version}, license: ${pkg.license}, author: ${pkg.author}`,
  `points: ${nPts} (unused by any triangle: ${unused})`,
  `triangles: ${nTri}`,
  `edges: ${undirected.size} (interior ${interiorEdges}, boundary ${boundaryEdges}, non-manifold ${nonManifoldEdges})`,
  `boundary loops: ${boundaryLoops}`,
  `degenerate triangles: ${degenerateIdx} with a repeated index, ${degenerateArea} with ~zero area`,
  `duplicate triangles: ${duplicateTris}`,
  `triangle area: min ${minArea.toExponential(3)}, max ${maxArea.toExponential(3)}`,
  `orientation consistent (each interior edge once per direction): ${consistent ? 'yes' : 'NO'} (${inconsistentEdges} inconsistent interior edges)`,
  `Euler characteristic V-E+F: ${nPts - undirected.size + nTri}`,
  `signed volume: ${signedVolume.toFixed(4)} (${signedVolume > 0 ? 'outward' : 'inward'}-facing if closed)`,
  `bounds: x [${lo[0]}, ${hi[0]}] y [${lo[1]}, ${hi[1]}] z [${lo[2]}, ${hi[2]}]`,
];
process.stdout.write(report.join('\n') + '\n');

// ---- write binary little-endian PLY -------------------------------------
const header =
  'ply\n' +
  'format binary_little_endian 1.0\n' +
  `comment Stanford bunny (Stanford 3D Scanning Repository), via npm package ${pkg.name} ${pkg.version}, ${pkg.license}\n` +
  'comment converted by Data/scripts/bunny_to_ply.js; orientation as in the package\n' +
  `element vertex ${nPts}\n` +
  'property float x\n' +
  'property float y\n' +
  'property float z\n' +
  `element face ${nTri}\n` +
  'property list uchar int vertex_indices\n' +
  'end_header\n';

const headerBuf = Buffer.from(header, 'ascii');
const body = Buffer.alloc(nPts * 12 + nTri * 13);
let off = 0;
for (const p of positions) {
  for (let k = 0; k < 3; k++) { body.writeFloatLE(p[k], off); off += 4; }
}
for (const c of cells) {
  body.writeUInt8(3, off); off += 1;
  for (let k = 0; k < 3; k++) { body.writeInt32LE(c[k], off); off += 4; }
}
fs.writeFileSync(outFile, Buffer.concat([headerBuf, body]));
process.stdout.write(`wrote ${outFile} (${headerBuf.length + body.length} bytes)\n`);
