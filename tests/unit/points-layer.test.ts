// The page's point-cloud layer (web/src/viewer/layers.ts PointsLayer): one THREE.Points over the
// worker's array (no copy), sprites of a fixed screen size, region colours mixed into the base colour;
// a subsampled cloud's left-out points drawn after it, as their stand-ins.
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { PointsLayer } from '../../web/src/viewer/layers.ts';

const positions = new Float32Array([0, 0, 0, 1, 0, 0, 0, 2, 0]);

describe('PointsLayer', () => {
  it('draws the given array as screen-sized points in one object', () => {
    const layer = new PointsLayer(positions, 2);
    expect(layer.object).toBeInstanceOf(THREE.Points);
    expect(layer.geometry.getAttribute('position').array).toBe(positions);
    expect(layer.object.material.sizeAttenuation).toBe(false);
    expect(layer.object.material.size).toBe(6); // 3 CSS pixels at a pixel ratio of 2
    expect(layer.vertexCount).toBe(3);
    expect(layer.vertexPosition(2).toArray()).toEqual([0, 2, 0]);
    expect(layer.boundingSphere.radius).toBeGreaterThan(0.9);
  });

  it('mixes region colours into the base colour, and back', () => {
    const layer = new PointsLayer(positions, 1);
    const colour = () => Array.from(layer.geometry.getAttribute('color').array as Float32Array);
    const base = colour();
    expect(base.slice(0, 3)).toEqual(base.slice(3, 6));
    const red = new Float32Array([1, 0, 0, 1, 0, 0, 1, 0, 0]);
    layer.setRegionColors(red, 1);
    expect(colour()).toEqual(Array.from(red));
    layer.setRegionColorMix(0.5);
    expect(colour()[0]).toBeCloseTo((base[0] + 1) / 2, 6);
    expect(colour()[1]).toBeCloseTo(base[1] / 2, 6);
    layer.setRegionColors(null);
    expect(colour()).toEqual(base);
  });

  it('draws the points a subsample left out after those computed on, coloured and picked as their stand-ins', () => {
    const leftOut = { positions: new Float32Array([0.1, 0, 0, 0, 1.9, 0]), standIn: new Uint32Array([0, 2]) };
    const layer = new PointsLayer(positions, 1, leftOut);
    expect(layer.vertexCount, 'the stages index the points computed on').toBe(3);
    expect(layer.drawnCount).toBe(5);
    expect(Array.from(layer.geometry.getAttribute('position').array)).toEqual([...positions, ...leftOut.positions]);
    expect([0, 1, 2, 3, 4].map((i) => layer.computedPoint(i))).toEqual([0, 1, 2, 0, 2]);
    const colour = (i: number) => Array.from((layer.geometry.getAttribute('color').array as Float32Array).subarray(3 * i, 3 * i + 3));
    layer.setScalarField({ values: new Float32Array([0, 1, 2]), max: 2, isolineSpacing: 0 });
    layer.setScalarVisible(true);
    expect(colour(0)).not.toEqual(colour(2));
    expect(colour(3)).toEqual(colour(0));
    expect(colour(4)).toEqual(colour(2));
    layer.setRegionColors(new Float32Array([1, 0, 0, 0, 1, 0, 0, 0, 1]), 1);
    layer.setScalarVisible(false);
    expect([colour(3), colour(4)]).toEqual([[1, 0, 0], [0, 0, 1]]);
    layer.setMoving(true);
    expect(layer.geometry.drawRange.count, 'moving: the computed points alone').toBe(3);
    // A ray down onto the left-out point at (0, 1.9, 0) picks its stand-in, point 2, also while moving.
    const raycaster = new THREE.Raycaster(new THREE.Vector3(0, 1.9, 5), new THREE.Vector3(0, 0, -1));
    raycaster.params.Points.threshold = 0.05;
    expect(layer.intersect(raycaster)?.point).toBe(2);
    expect(layer.intersect(raycaster)?.at.y).toBeCloseTo(1.9, 6);
    expect(layer.geometry.drawRange.count).toBe(3);
    layer.setMoving(false);
    expect(layer.geometry.drawRange.count).toBe(Infinity);
  });

  it('draws at most the points it is given a budget for, the computed ones first', () => {
    const leftOut = { positions: new Float32Array([0.1, 0, 0, 0, 1.9, 0]), standIn: new Uint32Array([0, 2]) };
    expect(new PointsLayer(positions, 1, leftOut, 4).drawnCount).toBe(4);
    expect(new PointsLayer(positions, 1, leftOut, 1).drawnCount).toBe(3);
    const four = new PointsLayer(positions, 1, leftOut, 4);
    expect(Array.from(four.geometry.getAttribute('position').array)).toEqual([...positions, ...leftOut.positions.subarray(0, 3)]);
    expect(four.computedPoint(3)).toBe(0);
  });

  it('turns see-through for the skeleton inside, and opaque again', () => {
    const layer = new PointsLayer(positions, 1);
    layer.setTranslucent(true);
    expect(layer.object.material.transparent).toBe(true);
    expect(layer.object.material.opacity).toBeLessThan(1);
    layer.setTranslucent(false);
    expect(layer.object.material.opacity).toBe(1);
  });
});
