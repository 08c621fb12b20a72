// Malformed inputs: each must throw a MeshFormatError whose one-line message starts with the format
// and names the line (text) or face (binary) at fault.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { MeshFormatError, parseMesh } from '../../lib/io/index.ts';
import { fixture, sharedData } from '../paths.ts';

const readFixture = (name: string) => new Uint8Array(readFileSync(fixture('formats', name)));
const text = (s: string) => new TextEncoder().encode(s);

/** Parses and returns the MeshFormatError's message (fails the test if nothing or something else is thrown). */
function errorOf(bytes: Uint8Array, fileName: string): string {
  try {
    parseMesh(bytes, fileName);
  } catch (error) {
    expect(error).toBeInstanceOf(MeshFormatError);
    const message = (error as Error).message;
    expect(message).not.toContain('\n');
    return message;
  }
  throw new Error(`${fileName} was parsed without error`);
}

const TRIANGLE_OBJ = 'v 0 0 0\nv 1 0 0\nv 0 1 0\n';
const PLY_HEADER = (vertices: number, faces: number, encoding = 'ascii') =>
  `ply\nformat ${encoding} 1.0\nelement vertex ${vertices}\nproperty float x\nproperty float y\nproperty float z\n` +
  `element face ${faces}\nproperty list uchar int vertex_indices\nend_header\n`;

describe('empty and unrecognisable files', () => {
  it.each(['obj', 'ply', 'stl', 'off'])('empty .%s', (ext) => {
    expect(errorOf(new Uint8Array(0), `empty.${ext}`)).toBe(`${ext.toUpperCase()}: file is empty`);
  });

  it('garbage text', () => {
    const garbage = text('hello world\nthis is not a mesh\n');
    expect(errorOf(garbage, 'g.obj')).toBe('OBJ: no vertices in file');
    expect(errorOf(garbage, 'g.off')).toBe("OFF: line 1: expected the OFF header, found 'hello'");
    expect(errorOf(garbage, 'g.ply')).toBe("PLY: missing 'ply' magic line");
    expect(errorOf(garbage, 'g.stl')).toMatch(/^STL: not an ASCII STL \(no 'solid' keyword\) and too short/);
    expect(errorOf(garbage, 'g.dat')).toMatch(/^unknown format: 'g.dat'/);
  });

  it('a binary file named .obj or .off', () => {
    const binary = new Uint8Array(300).map((_, i) => (i * 37) % 256);
    expect(errorOf(binary, 'b.obj')).toBe('OBJ: the file is binary, not a text OBJ file');
    expect(errorOf(binary, 'b.off')).toBe('OFF: the file is binary, not a text OFF file');
  });

  it('vertices but no faces', () => {
    expect(errorOf(text(TRIANGLE_OBJ + 'l 1 2\n'), 'x.obj')).toBe('OBJ: no faces in file but lines (a skeleton?): neither a mesh nor a point cloud');
    expect(errorOf(text('OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n'), 'x.off')).toBe('OFF: no faces in file');
    expect(errorOf(text(PLY_HEADER(1, 0) + '0 0 0\n'), 'x.ply')).toBe('PLY: the file is a point cloud (1 point, no faces), not a mesh');
    expect(errorOf(text('solid empty\nendsolid empty\n'), 'x.stl')).toBe('STL: no faces in file');
  });

  it('a point cloud PLY', () => {
    const cloud = new Uint8Array(readFileSync(`${sharedData}/pointclouds/bob_clean.ply`));
    expect(errorOf(cloud, 'bob_clean.ply')).toBe('PLY: the file is a point cloud (20000 points, no faces), not a mesh');
  });
});

describe('OBJ', () => {
  it('index out of range, zero, before the first vertex, not an integer', () => {
    expect(errorOf(text(TRIANGLE_OBJ + 'f 1 2 3\nf 1 2 9\n'), 'x.obj')).toBe(
      'OBJ: line 5: vertex index 9 is out of range (the file has 3 vertices)',
    );
    expect(errorOf(text(TRIANGLE_OBJ + 'f 0 1 2\n'), 'x.obj')).toBe('OBJ: line 4: vertex index 0 is invalid (OBJ indices start at 1)');
    expect(errorOf(text(TRIANGLE_OBJ + 'f -1 -2 -4\n'), 'x.obj')).toBe(
      'OBJ: line 4: relative vertex index -4 points before the first vertex',
    );
    expect(errorOf(text(TRIANGLE_OBJ + 'f 1 2.5 3\n'), 'x.obj')).toBe("OBJ: line 4: bad vertex index '2.5'");
    expect(errorOf(text(TRIANGLE_OBJ + 'f 1 2 x/1\n'), 'x.obj')).toBe("OBJ: line 4: bad vertex index 'x/1'");
  });

  it('a face with 2 vertices', () => {
    expect(errorOf(text(TRIANGLE_OBJ + 'f 1 2\n'), 'x.obj')).toBe('OBJ: line 4: face has 2 vertices, at least 3 are needed');
  });

  it('bad or missing coordinates, counting CRLF lines', () => {
    expect(errorOf(text('# c\r\nv 1 abc 3\r\n'), 'x.obj')).toBe("OBJ: line 2: bad number 'abc'");
    expect(errorOf(text('v 1 2\r\nf 1 1 1\r\n'), 'x.obj')).toBe('OBJ: line 1: expected a number, found the end of the line');
    expect(errorOf(text('v 1 2 # c\n'), 'x.obj')).toBe('OBJ: line 1: expected a number, found the end of the line');
    expect(errorOf(text('v 1 2'), 'x.obj')).toBe('OBJ: line 1: expected a number, found the end of the file');
    for (const bad of ['0x10', '1e', '1.5.2', '--1', 'infinite', '.']) {
      expect(errorOf(text(`v 1 ${bad} 2\n`), 'x.obj')).toBe(`OBJ: line 1: bad number '${bad}'`);
    }
  });
});

describe('OFF', () => {
  const cube = readFileSync(fixture('formats', 'cube.off'), 'latin1');

  it('wrong counts', () => {
    expect(errorOf(text(cube.replace('8 6 12', '8 7 12')), 'x.off')).toBe('OFF: file ends after 6 of 7 faces');
    // A ninth vertex swallows the first face line, so the faces run out.
    expect(errorOf(text(cube.replace('8 6 12', '9 6 12')), 'x.off')).toBe('OFF: file ends after 5 of 6 faces');
    expect(errorOf(text('OFF\n3 1 0\n0 0 0\n'), 'x.off')).toMatch(/^OFF: header claims 3 vertices and 1 faces but the file has only 6 bytes/);
  });

  it('index out of range, short faces, bad numbers', () => {
    expect(errorOf(text(cube.replace('4 1 2 6 5', '4 1 2 6 8')), 'x.off')).toBe(
      'OFF: line 21: vertex index 8 is out of range (the file has 8 vertices)',
    );
    expect(errorOf(text(cube.replace('4 1 2 6 5', '2 1 2')), 'x.off')).toBe('OFF: line 21: face 5 has 2 vertices, at least 3 are needed');
    expect(errorOf(text(cube.replace('4 1 2 6 5', '4 1 2 6')), 'x.off')).toBe(
      'OFF: line 21: expected vertex index, found the end of the line',
    );
    expect(errorOf(text(cube.replace('0.75 2 1.5', '0.75 two 1.5')), 'x.off')).toBe("OFF: line 13: bad number 'two'");
  });

  it('unsupported variants', () => {
    expect(errorOf(text('4OFF\n1 1 0\n0 0 0 0\n'), 'x.off')).toBe('OFF: 4OFF files (not 3D) are not supported');
    expect(errorOf(text('OFF BINARY\n'), 'x.off')).toBe('OFF: binary OFF files are not supported');
  });
});

describe('PLY', () => {
  it('a header claiming far more data than the file has fails fast', () => {
    const bytes = new Uint8Array(2000);
    const header = text(PLY_HEADER(100_000_000, 1, 'binary_little_endian'));
    bytes.set(header);
    const start = performance.now();
    expect(errorOf(bytes, 'huge.ply')).toBe(
      `PLY: header claims 100000000 vertices but the file has only ${2000 - header.length} bytes of data`,
    );
    expect(performance.now() - start).toBeLessThan(100);
    expect(errorOf(text(PLY_HEADER(3, 100_000_000) + '0 0 0\n1 0 0\n0 1 0\n'), 'huge.ply')).toBe(
      'PLY: header claims 100000000 faces but the file has only 18 bytes of data',
    );
  });

  it('truncated binary files', () => {
    const le = readFixture('cube_binary_le.ply');
    expect(errorOf(le.subarray(0, le.length - 300), 'x.ply')).toBe('PLY: file is truncated in face 5 of 12');
    const be = readFixture('cube_binary_be.ply');
    const dataStart = Buffer.from(be).indexOf('end_header\r\n') + 12;
    expect(errorOf(be.subarray(0, dataStart + 10), 'x.ply')).toBe('PLY: header claims 8 vertices but the file has only 10 bytes of data');
    // A long list in an element before the vertices leaves too little for them.
    const header = text(PLY_HEADER(3, 1, 'binary_little_endian').replace('element vertex', 'element blob 1\nproperty list uchar uchar data\nelement vertex'));
    const bytes = new Uint8Array(header.length + 1 + 200 + 30);
    bytes.set(header);
    bytes[header.length] = 200;
    expect(errorOf(bytes, 'x.ply')).toBe('PLY: file is truncated in vertex 2 of 3');
  });

  it('wrong counts in ascii', () => {
    const cube = readFileSync(fixture('formats', 'cube_ascii.ply'), 'latin1');
    expect(errorOf(text(cube.replace('element face 6', 'element face 7').replace(/2 0 1 0\.5[^]*$/, '')), 'x.ply')).toBe(
      'PLY: file ends after 6 of 7 faces',
    );
  });

  it('index out of range or not an integer, short faces', () => {
    const ascii = PLY_HEADER(3, 2) + '0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n';
    expect(errorOf(text(ascii), 'x.ply')).toBe('PLY: line 14: face 1: vertex index 3 is out of range (the file has 3 vertices)');
    expect(errorOf(text(ascii.replace('3 0 1 3', '2 0 1')), 'x.ply')).toBe('PLY: line 14: face 1 has 2 vertices, at least 3 are needed');

    const le = readFixture('cube_binary_le.ply');
    const view = new DataView(le.buffer, le.byteOffset, le.byteLength);
    const faceStart = le.length - 16 - 12 * 42; // 12 faces of 42 bytes, then 16 bytes of edges
    const broken = le.slice();
    new DataView(broken.buffer).setInt32(faceStart + 3 * 42 + 5 + 4, 8, true);
    expect(view.getUint8(faceStart + 3 * 42 + 4)).toBe(3);
    expect(errorOf(broken, 'x.ply')).toBe('PLY: face 3: vertex index 8 is out of range (the file has 8 vertices)');
    new DataView(broken.buffer).setUint8(faceStart + 3 * 42 + 4, 2);
    expect(errorOf(broken, 'x.ply')).toBe('PLY: face 3 has 2 vertices, at least 3 are needed');

    const floatIndices = text(PLY_HEADER(3, 1, 'binary_little_endian').replace('uchar int', 'uchar float'));
    const bytes = new Uint8Array(floatIndices.length + 36 + 13);
    bytes.set(floatIndices);
    const data = new DataView(bytes.buffer, floatIndices.length);
    data.setUint8(36, 3);
    [0, 1.5, 2].forEach((x, i) => data.setFloat32(37 + 4 * i, x, true));
    expect(errorOf(bytes, 'x.ply')).toBe('PLY: face 0: vertex index 1.5 is not an integer');
  });

  it('broken headers', () => {
    expect(errorOf(text('ply\nformat ascii 1.0\nelement vertex 3\n'), 'x.ply')).toBe("PLY: no 'end_header' line: the header is incomplete");
    expect(errorOf(text(PLY_HEADER(3, 1).replace('float x', 'float128 x')), 'x.ply')).toBe(
      "PLY: header line 4: expected 'property <type> <name>' with a known type",
    );
    expect(errorOf(text(PLY_HEADER(3, 1).replace('ascii', 'binary_middle_endian')), 'x.ply')).toBe(
      "PLY: header line 2: unknown format 'binary_middle_endian'",
    );
    expect(errorOf(text(PLY_HEADER(3, 1).replace('property float z\n', '')), 'x.ply')).toBe("PLY: vertex element has no 'z' property");
    expect(errorOf(text(PLY_HEADER(3, 1).replace('vertex_indices', 'corners')), 'x.ply')).toBe(
      "PLY: face element has no 'vertex_indices' list property",
    );
    expect(errorOf(text(PLY_HEADER(3, 1).replace('element vertex 3', 'element vertex -3')), 'x.ply')).toBe(
      "PLY: header line 3: expected 'element <name> <count>'",
    );
  });
});

describe('STL', () => {
  it('truncated binary STL', () => {
    const stl = readFixture('cube_binary.stl');
    // Its header starts with "solid" but the content is binary.
    expect(errorOf(stl.subarray(0, stl.length - 1), 'x.stl')).toBe(
      "STL: not an ASCII STL (binary content after 'solid') and not a binary STL: 12 triangles need 684 bytes but the file has 683",
    );
    const unnamed = new Uint8Array(stl.length + 1);
    unnamed.set(stl);
    unnamed.set(text('bin!!'));
    expect(errorOf(unnamed, 'x.stl')).toBe(
      "STL: not an ASCII STL (no 'solid' keyword) and not a binary STL: 12 triangles need 684 bytes but the file has 685",
    );
  });

  it('bad ASCII STL', () => {
    const facet = (corners: string) => `solid s\nfacet normal 0 0 1\nouter loop\n${corners}endloop\nendfacet\nendsolid s\n`;
    expect(errorOf(text(facet('vertex 0 0 0\nvertex 1 0 0\n')), 'x.stl')).toBe('STL: line 6: facet has 2 vertices, at least 3 are needed');
    expect(errorOf(text(facet('vertex 0 0 0\nvertex 1 0 0\nvertex 0 one 0\n')), 'x.stl')).toBe("STL: line 6: bad number 'one'");
    expect(errorOf(text(facet('vertex 0 0 0\nvertex 1 0 0\nvertx 0 1 0\n')), 'x.stl')).toBe(
      "STL: line 6: unexpected 'vertx' (expected facet, vertex, endloop...)",
    );
  });
});
