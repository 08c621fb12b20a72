// Every format and variant of the fixture cube must read as the same mesh, and the content wins
// over a misleading file extension.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { MESH_EXTENSIONS, formatFromName, parseMesh, type ParsedMesh } from '../../lib/io/index.ts';
import { fixture } from '../paths.ts';

const readFixture = (name: string) => new Uint8Array(readFileSync(fixture('formats', name)));
const text = (s: string) => new TextEncoder().encode(s);

/** The fixture cube as it is written in cube.off (quads fan-triangulated). */
const CUBE_POSITIONS = [
  -1.25, 0, -0.5, 0.75, 0, -0.5, 0.75, 2, -0.5, -1.25, 2, -0.5,
  -1.25, 0, 1.5, 0.75, 0, 1.5, 0.75, 2, 1.5, -1.25, 2, 1.5,
];
const CUBE_TRIANGLES = [0, 3, 2, 0, 2, 1, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 2, 3, 7, 2, 7, 6, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5];

/**
 * The mesh as a sorted list of triangles given by corner coordinates, each rotated to start at its
 * smallest corner: equal for meshes that differ only in vertex numbering (STL merging order).
 */
function canonical(mesh: { positions: ArrayLike<number>; triangles: ArrayLike<number> }): string[] {
  const corner = (v: number) => `${mesh.positions[3 * v]},${mesh.positions[3 * v + 1]},${mesh.positions[3 * v + 2]}`;
  const result: string[] = [];
  for (let t = 0; t < mesh.triangles.length; t += 3) {
    const c = [0, 1, 2].map((i) => corner(mesh.triangles[t + i]));
    const first = c.indexOf([...c].sort()[0]);
    result.push([0, 1, 2].map((i) => c[(first + i) % 3]).join(' | '));
  }
  return result.sort();
}

const CUBE = canonical({ positions: CUBE_POSITIONS, triangles: CUBE_TRIANGLES });

describe('fixture cube in every format', () => {
  const cases: [file: string, format: ParsedMesh['format'], warnings: RegExp[]][] = [
    ['cube.obj', 'obj', [/split 6 polygons/]],
    ['cube_negative_crlf.obj', 'obj', []],
    ['cube.off', 'off', [/split 6 polygons/]],
    ['cube_colors.off', 'off', [/split 6 polygons/]],
    ['cube_ascii.ply', 'ply', [/split 6 polygons/]],
    ['cube_binary_le.ply', 'ply', []],
    ['cube_binary_be.ply', 'ply', [/split 6 polygons/]],
    ['cube_ascii.stl', 'stl', []],
    ['cube_binary.stl', 'stl', []],
  ];

  it.each(cases)('%s reads as the cube', (file, format, warnings) => {
    const mesh = parseMesh(readFixture(file), file);
    expect(mesh.format).toBe(format);
    expect(mesh.positions).toBeInstanceOf(Float64Array);
    expect(mesh.triangles).toBeInstanceOf(Uint32Array);
    expect(mesh.positions.length).toBe(24);
    expect(canonical(mesh)).toEqual(CUBE);
    expect(mesh.warnings).toHaveLength(warnings.length);
    warnings.forEach((w, i) => expect(mesh.warnings[i]).toMatch(w));
    if (format !== 'stl') {
      // Indexed formats keep the file's vertex order and the fan split of each quad.
      expect(Array.from(mesh.positions)).toEqual(CUBE_POSITIONS);
      expect(Array.from(mesh.triangles)).toEqual(CUBE_TRIANGLES);
    }
  });
});

describe('format detection', () => {
  it('maps extensions case-insensitively', () => {
    expect(formatFromName('a/b/Model.PLY')).toBe('ply');
    expect(formatFromName('x.obj')).toBe('obj');
    expect(formatFromName('x.Stl')).toBe('stl');
    expect(formatFromName('x.off')).toBe('off');
    expect(formatFromName('x.tar.gz')).toBeNull();
    expect(formatFromName('obj')).toBeNull();
    expect(formatFromName('dir.obj/file')).toBeNull();
    expect(MESH_EXTENSIONS).toEqual(['.obj', '.ply', '.stl', '.off', '.glb']);
  });

  it('reads PLY content named .obj as PLY, with a warning', () => {
    const mesh = parseMesh(readFixture('cube_binary_le.ply'), 'cube.obj');
    expect(mesh.format).toBe('ply');
    expect(canonical(mesh)).toEqual(CUBE);
    expect(mesh.warnings[0]).toMatch(/named like OBJ but contains PLY/);
  });

  it('reads a binary STL named .ply as STL', () => {
    const mesh = parseMesh(readFixture('cube_binary.stl'), 'cube.ply');
    expect(mesh.format).toBe('stl');
    expect(canonical(mesh)).toEqual(CUBE);
    expect(mesh.warnings[0]).toMatch(/contains STL/);
  });

  it('sniffs the content of files with an unknown extension', () => {
    for (const [file, format] of [['cube.obj', 'obj'], ['cube_colors.off', 'off'], ['cube_ascii.stl', 'stl'], ['cube_binary_be.ply', 'ply']]) {
      const mesh = parseMesh(readFixture(file), 'upload.bin');
      expect(mesh.format).toBe(format);
      expect(canonical(mesh)).toEqual(CUBE);
      expect(mesh.warnings[0]).toMatch(/unknown file extension/);
    }
  });
});

describe('variants', () => {
  it('passes NaN and infinite coordinates through (the core reports them)', () => {
    const mesh = parseMesh(text('v nan 0 0\nv inf -Infinity 1e400\nv 0 1 -inf\nf 1 2 3\n'), 'x.obj');
    expect(Array.from(mesh.positions)).toEqual([NaN, 0, 0, Infinity, -Infinity, Infinity, 0, 1, -Infinity]);
  });

  it('parses numbers exactly, including long mantissas and big exponents', () => {
    const values = ['0.1', '-0.30000000000000004', '1.7976931348623157e308', '5e-324', '123456789012345678901234', '2.5E-7'];
    const mesh = parseMesh(text(`v ${values.slice(0, 3).join(' ')}\nv ${values.slice(3).join(' ')}\nv 0 0 0\nf 1 2 3\n`), 'x.obj');
    expect(Array.from(mesh.positions.slice(0, 6))).toEqual(values.map(Number));
  });

  it('accepts OBJ faces before the vertices they use, and PLY faces before vertices', () => {
    expect(parseMesh(text('f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n'), 'x.obj').triangles).toEqual(new Uint32Array([0, 1, 2]));
    const ply = 'ply\nformat ascii 1.0\nelement face 1\nproperty list uchar uint vertex_indices\n' +
      'element vertex 3\nproperty double z\nproperty double y\nproperty double x\nend_header\n3 2 1 0\n1 0 0\n0 1 0\n0 0 1\n';
    const mesh = parseMesh(text(ply), 'x.ply');
    expect(Array.from(mesh.positions)).toEqual([0, 0, 1, 0, 1, 0, 1, 0, 0]);
    expect(Array.from(mesh.triangles)).toEqual([2, 1, 0]);
  });

  it('reads OFF without the header keyword and NOFF/STCOFF extra values', () => {
    const body = '3 1 0\n0 0 0 {}\n1 0 0 {}\n0 1 0 {}\n3 0 1 2\n';
    expect(parseMesh(text(body.replaceAll(' {}', '')), 'x.off').triangles).toEqual(new Uint32Array([0, 1, 2]));
    expect(parseMesh(text('NOFF\n' + body.replaceAll('{}', '0 0 1')), 'x.off').positions[3]).toBe(1);
    expect(parseMesh(text('STCOFF\n' + body.replaceAll('{}', '0.5 0.5 1 0 0 1')), 'x.off').positions[7]).toBe(1);
  });

  it('fan-triangulates ASCII STL loops with more than 3 vertices', () => {
    const stl = 'solid q\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid q\n';
    const mesh = parseMesh(text(stl), 'q.stl');
    expect(Array.from(mesh.triangles)).toEqual([0, 1, 2, 0, 2, 3]);
    expect(mesh.warnings).toEqual(['split 1 facets with more than 3 vertices into triangles']);
  });

  it('warns when STL triangles share no vertex', () => {
    const stl = 'solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n' +
      'facet normal 0 0 1\nouter loop\nvertex 5 0 0\nvertex 6 0 0\nvertex 5 1 0\nendloop\nendfacet\nendsolid s\n';
    expect(parseMesh(text(stl), 's.stl').warnings).toEqual(['no two triangles share a vertex (the mesh is a triangle soup)']);
  });

  it('merges STL corners at -0 and +0', () => {
    const stl = 'solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n' +
      'facet normal 0 0 1\nouter loop\nvertex -0 -0 0\nvertex 0 -1 0\nvertex 1 0 -0\nendloop\nendfacet\nendsolid s\n';
    const mesh = parseMesh(text(stl), 's.stl');
    expect(mesh.positions.length / 3).toBe(4);
    expect(Array.from(mesh.triangles)).toEqual([0, 1, 2, 0, 3, 1]);
  });
});
