// The page's point-cloud layer (web/src/viewer/layers.ts PointsLayer): one THREE.Points over the
// worker's array (no copy), sprites of a fixed screen size, region colours mixed into the base colour.
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

  it('turns see-through for the skeleton inside, and opaque again', () => {
    const layer = new PointsLayer(positions, 1);
    layer.setTranslucent(true);
    expect(layer.object.material.transparent).toBe(true);
    expect(layer.object.material.opacity).toBeLessThan(1);
    layer.setTranslucent(false);
    expect(layer.object.material.opacity).toBe(1);
  });
});
