// Point-cloud reading (lib/io: PLY and OBJ without faces, text point lists): every variant reads the
// same points, bad input gives one-line MeshFormatErrors naming the line, and parseMesh refuses clouds.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import {
  CLOUD_EXTENSIONS, MESH_EXTENSIONS, MeshFormatError, SHAPE_EXTENSIONS, formatFromName, parseMesh, parseShape, type ParsedCloud,
} from '../../lib/io/index.ts';
import { fixture } from '../paths.ts';
import { cloudPly, type PlyEncoding } from './support/clouds.ts';

const text = (s: string) => new TextEncoder().encode(s);

/** Four points and their normals, all exact in float32. */
const POINTS = [[0, 0, 0], [1.5, -2, 0.25], [-0.125, 3, 1], [2, 2, -4]];
const NORMALS = [[0, 0, 1], [1, 0, 0], [0, -1, 0], [0.6, 0.8, 0]];
const FLAT_POINTS = POINTS.flat();
const FLAT_NORMALS = NORMALS.flat();

function cloud(bytes: Uint8Array, fileName: string): ParsedCloud {
  const shape = parseShape(bytes, fileName);
  expect(shape.kind).toBe('cloud');
  return shape as ParsedCloud;
}

/** The MeshFormatError's message (fails the test if nothing or something else is thrown). */
function errorOf(read: () => unknown): string {
  try {
    read();
  } catch (error) {
    expect(error).toBeInstanceOf(MeshFormatError);
    const { message } = error as Error;
    expect(message).not.toContain('\n');
    return message;
  }
  throw new Error('read without error');
}

const shapeError = (s: string, fileName: string) => errorOf(() => parseShape(text(s), fileName));

describe('PLY point clouds', () => {
  const encodings: PlyEncoding[] = ['ascii', 'binary_little_endian', 'binary_big_endian'];
  const cases = encodings.flatMap((encoding) => (['float', 'double'] as const).flatMap((type) => [true, false].map((withNormals) => [encoding, type, withNormals] as const)));

  it.each(cases)('%s %s, normals %s', (encoding, type, withNormals) => {
    const read = cloud(cloudPly(POINTS, withNormals ? NORMALS : null, encoding, type), 'c.ply');
    expect(read.format).toBe('ply');
    expect(read.positions).toBeInstanceOf(Float64Array);
    expect(Array.from(read.positions)).toEqual(FLAT_POINTS);
    if (withNormals) {
      expect(read.normals).toBeInstanceOf(Float32Array);
      expect(Array.from(read.normals!)).toEqual(FLAT_NORMALS.map(Math.fround));
    } else {
      expect(read.normals).toBeNull();
    }
    expect(read.warnings).toEqual([]);
  });

  it('a face element of 0 rows, other properties, a list in the vertex rows', () => {
    const ply = 'ply\nformat ascii 1.0\nelement vertex 2\nproperty uchar red\nproperty float x\nproperty list uchar int neighbours\n'
      + 'property float y\nproperty float nz\nproperty float z\nproperty float nx\nproperty float ny\nelement face 0\n'
      + 'property list uchar int vertex_indices\nend_header\n255 1 2 7 8 2 0 3 1 0\n0 4 0 5 1 6 0 0\n';
    const read = cloud(text(ply), 'c.ply');
    expect(Array.from(read.positions)).toEqual([1, 2, 3, 4, 5, 6]);
    expect(Array.from(read.normals!)).toEqual([1, 0, 0, 0, 0, 1]);
  });

  it('normals only when all of nx, ny, nz are there', () => {
    const ply = 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n'
      + 'property float nx\nproperty float ny\nend_header\n1 2 3 0 1\n';
    const read = cloud(text(ply), 'c.ply');
    expect(read.normals).toBeNull();
    expect(read.warnings).toEqual(['the vertices have nx, ny but not all of nx, ny, nz: read without normals']);
  });

  it('refuses vertices joined by edges (a skeleton), no vertices, and data cut short', () => {
    const header = (vertices: number) => `ply\nformat ascii 1.0\nelement vertex ${vertices}\nproperty float x\nproperty float y\nproperty float z\n`;
    expect(shapeError(`${header(2)}element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n0 0 0\n1 1 1\n0 1\n`, 's.ply'))
      .toBe("PLY: no faces in file but an 'edge' element (a skeleton?): neither a mesh nor a point cloud");
    expect(shapeError(`${header(0)}end_header\n`, 'c.ply')).toBe('PLY: no vertices in file');
    expect(shapeError(`${header(3)}end_header\n0.5 0.5 0.5\n1.25 1.25 1.25\n`, 'c.ply')).toBe('PLY: file ends after 2 of 3 vertices');
    const binary = cloudPly(POINTS, NORMALS, 'binary_little_endian', 'float');
    expect(errorOf(() => parseShape(binary.subarray(0, binary.length - 5), 'c.ply'))).toMatch(/^PLY: header claims 4 vertices but the file has only \d+ bytes of data$/);
  });
});

describe('text point lists', () => {
  const expectPoints = (read: ParsedCloud, normals: number[] | null, warnings: string[] = []) => {
    expect(read.format).toBe('xyz');
    expect(Array.from(read.positions)).toEqual(FLAT_POINTS);
    expect(read.normals && Array.from(read.normals)).toEqual(normals && normals.map(Math.fround));
    expect(read.warnings).toEqual(warnings);
  };
  const rows = (separator: string, withNormals = false) => POINTS.map((p, i) => (withNormals ? [...p, ...NORMALS[i]] : p).join(separator));

  it.each(['.xyz', '.pts', '.txt', '.csv', '.XYZ'])('reads %s', (ext) => {
    expectPoints(cloud(text(rows(' ').join('\n')), `points${ext}`), null);
  });

  it('comments, blank lines, CRLF and any separators', () => {
    const file = `# exported by hand\r\n\r\n// a C++ comment\r\n${POINTS[0].join('\t')}\r\n${POINTS[1].join(', ')} # inline\r\n`
      + `  ${POINTS[2].join(';  ')}\r\n\r\n${POINTS[3].join(' \t,')}`;
    expectPoints(cloud(text(file), 'c.xyz'), null);
  });

  it('a header of column names, in any order, with extra columns', () => {
    expectPoints(cloud(text(['x,y,z,nx,ny,nz', ...rows(',', true)].join('\n')), 'c.csv'), FLAT_NORMALS);
    const shuffled = ['"NZ";"z";"Normal_X";"y";"ny";"x";"intensity"', ...POINTS.map((p, i) => [NORMALS[i][2], p[2], NORMALS[i][0], p[1], NORMALS[i][1], p[0], 7].join(';'))];
    expectPoints(cloud(text(shuffled.join('\n')), 'c.csv'), FLAT_NORMALS, ['ignored the column "intensity"']);
    expectPoints(cloud(text(['X Y Z R G B', ...POINTS.map((p) => `${p.join(' ')} 255 0 0`)].join('\n')), 'c.txt'), null, ['ignored the columns R, G, B']);
  });

  it('a commented header with as many names as columns (CloudCompare)', () => {
    expectPoints(cloud(text(['//X,Y,Z,Nx,Ny,Nz', ...rows(',', true)].join('\n')), 'c.txt'), FLAT_NORMALS);
    // A comment that does not match the columns is only a comment.
    expectPoints(cloud(text(['# x y z of the scan, in metres', ...rows(' ')].join('\n')), 'c.txt'), null);
  });

  it('without a header: columns 4-6 are normals only when they are unit vectors on every row', () => {
    expectPoints(cloud(text(rows(' ', true).join('\n')), 'c.xyz'), FLAT_NORMALS, ['read columns 1-3 as x y z and columns 4-6 as normals (unit vectors on every row)']);
    const withColour = POINTS.map((p, i) => [...p, ...NORMALS[i], 200, 100, 50].join(' '));
    expectPoints(cloud(text(withColour.join('\n')), 'c.xyz'), FLAT_NORMALS, [
      'read columns 1-3 as x y z and columns 4-6 as normals (unit vectors on every row), and ignored columns 7-9',
    ]);
    const colours = POINTS.map((p) => `${p.join(' ')} 1 0 0`).concat(`${POINTS[0].join(' ')} 0.5 0.5 0.5`);
    const read = cloud(text(colours.join('\n')), 'c.xyz');
    expect(read.normals).toBeNull();
    expect(read.warnings).toEqual(['read columns 1-3 as x y z and ignored columns 4-6 (columns 4-6 are not unit vectors on every row, so not normals)']);
    expectPoints(cloud(text(POINTS.map((p) => `${p.join(' ')} 0.5`).join('\n')), 'c.xyz'), null, ['read columns 1-3 as x y z and ignored column 4']);
  });

  it('count lines, as in .pts files with several scans', () => {
    const leica = ['2', ...POINTS.slice(0, 2).map((p) => `${p.join(' ')} -1200 10 20 30`), '2', ...POINTS.slice(2).map((p) => `${p.join(' ')} 5 10 20 30`)];
    expectPoints(cloud(text(leica.join('\n')), 'scan.pts'), null, ['read columns 1-3 as x y z and ignored columns 4-7 (columns 4-6 are not unit vectors on every row, so not normals)']);
    expectPoints(cloud(text(['4', ...rows(' ')].join('\n')), 'c.pts'), null);
  });

  it('semicolons with decimal commas (spreadsheet exports)', () => {
    const european = POINTS.map((p) => p.map((x) => String(x).replace('.', ',')).join(';'));
    expectPoints(cloud(text(['x;y;z', ...european].join('\n')), 'c.csv'), null);
  });

  it('passes NaN and infinities on (the cloud checks drop them)', () => {
    const read = cloud(text('1 2 3\nnan 0 0\n0 -inf 0\n'), 'c.xyz');
    expect(Array.from(read.positions)).toEqual([1, 2, 3, NaN, 0, 0, 0, -Infinity, 0]);
  });

  it('malformed rows, headers and counts', () => {
    expect(shapeError('1 2 3\n4 5\n', 'c.xyz')).toBe('XYZ: line 2: expected at least 3 numbers (x y z), found 2');
    expect(shapeError('1 2 3\n\n# c\n4 5 abc\n', 'c.xyz')).toBe("XYZ: line 4: bad number 'abc'");
    expect(shapeError('1 2 3\n4 5 6 7\n', 'c.xyz')).toBe('XYZ: line 2: 4 columns, but the first row has 3');
    expect(shapeError('1,2,3\n4,,5\n', 'c.csv')).toBe('XYZ: line 2: expected at least 3 numbers (x y z), found 2');
    expect(shapeError('a,b,c\n1,2,3\n', 'c.csv')).toBe("XYZ: line 1: expected numbers or a header of column names with x, y and z, found 'a b c'");
    expect(shapeError('x y z nx\n1 2 3\n', 'c.csv')).toBe('XYZ: line 2: 3 columns, but the header (line 1) names 4');
    expect(shapeError('3\n1 2 3\n4 5 6\n', 'c.pts')).toBe('XYZ: line 1: the count line says 3 points, but 2 rows follow');
    expect(shapeError('1\n1 2 3\n4 5 6\n', 'c.pts')).toBe('XYZ: line 3: more rows than the 1 that the count line (line 1) says');
    expect(shapeError('1 2 3\n7\n4 5 6\n', 'c.xyz')).toBe('XYZ: line 2: expected at least 3 numbers (x y z), found 1');
    expect(shapeError('# nothing\n\n', 'c.xyz')).toBe('XYZ: no points in file');
    expect(errorOf(() => parseShape(new Uint8Array(0), 'c.csv'))).toBe('XYZ: file is empty');
    expect(errorOf(() => parseShape(Uint8Array.from({ length: 300 }, (_, i) => (i * 37) % 256), 'c.xyz'))).toBe('XYZ: the file is binary, not a text XYZ file');
  });
});

describe('OBJ point clouds', () => {
  const vLines = POINTS.map((p) => `v ${p.join(' ')}`);

  it('v lines only', () => {
    const read = cloud(text(`# cloud\n${vLines.join('\n')}\n`), 'c.obj');
    expect(read.format).toBe('obj');
    expect(Array.from(read.positions)).toEqual(FLAT_POINTS);
    expect(read.normals).toBeNull();
    expect(read.warnings).toEqual([]);
  });

  it('vn lines: the n-th for the n-th vertex when there are as many, else ignored', () => {
    const paired = POINTS.map((p, i) => `vn ${NORMALS[i].join(' ')}\nv ${p.join(' ')}`).join('\n');
    expect(Array.from(cloud(text(paired), 'c.obj').normals!)).toEqual(FLAT_NORMALS.map(Math.fround));
    const fewer = cloud(text(`${vLines.join('\n')}\nvn 0 0 1\n`), 'c.obj');
    expect(fewer.normals).toBeNull();
    expect(fewer.warnings).toEqual(['ignored the normals (vn): the file has 1 of them for 4 vertices, so which belongs to which vertex is not known']);
  });

  it('faces make a mesh, whose vn lines are not read', () => {
    const mesh = parseShape(text(`${vLines.join('\n')}\nvn not a number\nf 1 2 3\n`), 'm.obj');
    expect(mesh.kind).toBe('mesh');
  });

  it('refuses vertices joined by lines (a skeleton) and bad vn lines of a cloud', () => {
    expect(shapeError(`${vLines.join('\n')}\nl 1 2 3\n`, 's.obj')).toBe('OBJ: no faces in file but lines (a skeleton?): neither a mesh nor a point cloud');
    expect(shapeError('v 0 0 0\nvn 0 x 1\n', 'c.obj')).toBe("OBJ: line 2: bad number 'x'");
  });
});

describe('parseShape and parseMesh', () => {
  it('knows the extensions', () => {
    expect(MESH_EXTENSIONS).toEqual(['.obj', '.ply', '.stl', '.off', '.glb']);
    expect(CLOUD_EXTENSIONS).toEqual(['.ply', '.obj', '.xyz', '.pts', '.txt', '.csv']);
    expect(SHAPE_EXTENSIONS).toEqual(['.obj', '.ply', '.stl', '.off', '.glb', '.xyz', '.pts', '.txt', '.csv']);
    expect(['a.xyz', 'a.PTS', 'a.txt', 'a.csv', 'a.ply', 'a.dat'].map(formatFromName)).toEqual(['xyz', 'xyz', 'xyz', 'xyz', 'ply', null]);
  });

  it('reads numeric rows of unknown extension as a point list, and nothing else', () => {
    const read = cloud(text(`# scan\n${POINTS.map((p) => p.join(' ')).join('\n')}\n`), 'scan.dat');
    expect(Array.from(read.positions)).toEqual(FLAT_POINTS);
    expect(read.warnings).toEqual(['unknown file extension; read the file as XYZ, which its content looks like']);
    expect(shapeError('x y z\n1 2 3\n', 'scan.dat')).toMatch(/^unknown format: 'scan.dat' has no .obj, .ply, .stl, .off, .glb, .xyz, .pts, .txt, .csv extension/);
    expect(shapeError('1 2\n3 4\n', 'scan.dat')).toMatch(/^unknown format/);
  });

  it('a point list named .txt that holds a mesh is read as the mesh', () => {
    const mesh = parseShape(text('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n'), 'mesh.txt');
    expect(mesh.kind).toBe('mesh');
    expect(mesh.warnings).toEqual(['the file is named like XYZ but contains OBJ; read it as OBJ']);
  });

  it('a headerless OFF file is not taken for a point list', () => {
    expect(parseShape(text('3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n'), 'm.off').kind).toBe('mesh');
  });

  it('parseMesh refuses a point cloud of any format', () => {
    const refuse = (bytes: Uint8Array, fileName: string) => errorOf(() => parseMesh(bytes, fileName));
    expect(refuse(cloudPly(POINTS, null, 'ascii', 'float'), 'c.ply')).toBe('PLY: the file is a point cloud (4 points, no faces), not a mesh');
    expect(refuse(text('v 1 2 3\n'), 'c.obj')).toBe('OBJ: the file is a point cloud (1 point, no faces), not a mesh');
    expect(refuse(text('1 2 3\n4 5 6\n'), 'c.xyz')).toBe('XYZ: the file is a point cloud (2 points, no faces), not a mesh');
  });
});

describe('real point clouds', () => {
  const read = (name: string) => cloud(new Uint8Array(readFileSync(fixture('clouds', name))), name);
  /** [min x, min y, min z, max x, max y, max z] */
  const box = (positions: Float64Array) => [0, 1, 2].map((k) => Math.min(...positions.filter((_, i) => i % 3 === k)))
    .concat([0, 1, 2].map((k) => Math.max(...positions.filter((_, i) => i % 3 === k))));

  it('bob, subsampled: the header count, normals of unit length, the box of the full cloud', () => {
    const bob = read('bob_subsample.ply');
    expect(bob.positions.length).toBe(3 * 1948);
    expect(bob.normals).not.toBeNull();
    for (let i = 0; i < 1948; i++) expect(Math.hypot(...bob.normals!.subarray(3 * i, 3 * i + 3))).toBeCloseTo(1, 5);
    // Nearly all of the box of the shared bob_clean.ply (diagonal 2.554 in its MANIFEST.md), and within it.
    const corners = box(bob.positions);
    const [x0, y0, z0, x1, y1, z1] = corners;
    expect(Math.hypot(x1 - x0, y1 - y0, z1 - z0)).toBeCloseTo(2.552, 3);
    const full = [-0.91269, -0.51128, -0.73101, 0.94292, 0.46055, 0.73105];
    corners.forEach((x, k) => expect(k < 3 ? x >= full[k] : x <= full[k]).toBe(true));
  });

  it('the GEL armadillo points: the header count, no normals, the diagonal of the MANIFEST', () => {
    const armadillo = read('armadillo_gel_pts.ply');
    expect(armadillo.positions.length).toBe(3 * 6488);
    expect(armadillo.normals).toBeNull();
    const [x0, y0, z0, x1, y1, z1] = box(armadillo.positions);
    expect(Math.hypot(x1 - x0, y1 - y0, z1 - z0)).toBeCloseTo(229.2, 1);
  });
});
