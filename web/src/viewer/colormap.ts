import * as THREE from 'three';

export type Rgb = [number, number, number];

/**
 * Turbo (Google, Apache-2.0), polynomial fit by Anton Mikhailov: a perceptual rainbow that keeps
 * the ends dark. t in [0, 1] -> sRGB in [0, 1].
 */
export function turbo(t: number): Rgb {
  const x = Math.min(1, Math.max(0, t));
  const x2 = x * x, x3 = x2 * x, x4 = x2 * x2, x5 = x4 * x;
  const r = 0.13572138 + 4.6153926 * x - 42.66032258 * x2 + 132.13108234 * x3 - 152.94239396 * x4 + 59.28637943 * x5;
  const g = 0.09140261 + 2.19418839 * x + 4.84296658 * x2 - 14.18503333 * x3 + 4.27729857 * x4 + 2.82956604 * x5;
  const b = 0.1066733 + 12.64194608 * x - 60.58204836 * x2 + 110.36276771 * x3 - 89.90310912 * x4 + 27.34824973 * x5;
  const c = (v: number) => Math.min(1, Math.max(0, v));
  return [c(r), c(g), c(b)];
}

/** A 256x1 sRGB lookup texture of a colormap, for shaders. */
export function colormapTexture(map: (t: number) => Rgb = turbo, size = 256): THREE.DataTexture {
  const data = new Uint8Array(size * 4);
  for (let i = 0; i < size; i++) {
    const [r, g, b] = map(i / (size - 1));
    data.set([Math.round(r * 255), Math.round(g * 255), Math.round(b * 255), 255], i * 4);
  }
  const texture = new THREE.DataTexture(data, size, 1, THREE.RGBAFormat);
  texture.colorSpace = THREE.SRGBColorSpace;
  texture.magFilter = THREE.LinearFilter;
  texture.minFilter = THREE.LinearFilter;
  texture.wrapS = texture.wrapT = THREE.ClampToEdgeWrapping;
  texture.needsUpdate = true;
  return texture;
}

/** A CSS linear-gradient of a colormap, left to right, for legends. */
export function colormapGradient(map: (t: number) => Rgb = turbo, stops = 16): string {
  const parts: string[] = [];
  for (let i = 0; i <= stops; i++) {
    const [r, g, b] = map(i / stops).map((v) => Math.round(v * 255));
    parts.push(`rgb(${r} ${g} ${b}) ${((100 * i) / stops).toFixed(1)}%`);
  }
  return `linear-gradient(to right, ${parts.join(', ')})`;
}

/** A round isoline spacing (1, 2 or 5 times a power of ten) giving about `count` lines up to `max`. */
export function niceSpacing(max: number, count = 16): number {
  if (!(max > 0) || !Number.isFinite(max)) return 0;
  const raw = max / count;
  const power = 10 ** Math.floor(Math.log10(raw));
  const m = raw / power;
  return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * power;
}
