/** Pixel statistics of the page's WebGL canvas (rendered with preserveDrawingBuffer). */
import { expect, type Page } from '@playwright/test';

export interface PixelStats {
  width: number;
  height: number;
  /** Opaque pixels: the canvas is cleared to transparent, so these are drawn geometry. */
  covered: number;
  coveredFraction: number;
  /** Mean and standard deviation of luminance (0..1) over covered pixels: lighting shows as spread. */
  meanLuminance: number;
  luminanceStd: number;
  /** Fraction of covered pixels that are clearly coloured (HSV saturation > 0.35). */
  saturatedFraction: number;
  /** Hue bins (of 24) holding at least 0.5 % of the covered pixels among saturated ones. */
  hueBins: number;
  /** A covered pixel near the middle of the drawn geometry, in CSS px from the canvas's top left. */
  meshPoint: { x: number; y: number } | null;
  /** 32x18 grid of mean premultiplied RGB (0..255), for comparing frames. */
  thumb: number[];
}

export async function canvasStats(page: Page): Promise<PixelStats> {
  return page.evaluate(() => {
    const canvas = document.querySelector<HTMLCanvasElement>('[data-testid="viewport-canvas"]');
    if (!canvas) throw new Error('no canvas');
    const { width, height } = canvas;
    const copy = document.createElement('canvas');
    copy.width = width;
    copy.height = height;
    const ctx = copy.getContext('2d', { willReadFrequently: true })!;
    ctx.drawImage(canvas, 0, 0);
    const data = ctx.getImageData(0, 0, width, height).data;

    const GX = 32, GY = 18, BINS = 24;
    const thumb = new Array<number>(GX * GY * 3).fill(0);
    const cellCount = new Array<number>(GX * GY).fill(0);
    const bins = new Array<number>(BINS).fill(0);
    let covered = 0, saturated = 0, lumSum = 0, lumSq = 0, cx = 0, cy = 0;
    for (let y = 0; y < height; y++) {
      for (let x = 0; x < width; x++) {
        const i = 4 * (y * width + x);
        const a = data[i + 3] / 255;
        const r = data[i] / 255, g = data[i + 1] / 255, b = data[i + 2] / 255;
        const cell = Math.floor((y * GY) / height) * GX + Math.floor((x * GX) / width);
        thumb[3 * cell] += r * a * 255;
        thumb[3 * cell + 1] += g * a * 255;
        thumb[3 * cell + 2] += b * a * 255;
        cellCount[cell]++;
        if (a < 0.98) continue;
        covered++;
        cx += x;
        cy += y;
        const lum = 0.2126 * r + 0.7152 * g + 0.0722 * b;
        lumSum += lum;
        lumSq += lum * lum;
        const max = Math.max(r, g, b), min = Math.min(r, g, b);
        if (max > 0.12 && (max - min) / max > 0.35) {
          saturated++;
          const d = max - min;
          let h = max === r ? (g - b) / d : max === g ? 2 + (b - r) / d : 4 + (r - g) / d;
          h = (h / 6 + 1) % 1;
          bins[Math.min(BINS - 1, Math.floor(h * BINS))]++;
        }
      }
    }
    for (let c = 0; c < GX * GY; c++) for (let k = 0; k < 3; k++) thumb[3 * c + k] /= Math.max(1, cellCount[c]);

    let meshPoint: { x: number; y: number } | null = null;
    if (covered > 0) {
      cx /= covered;
      cy /= covered;
      // The covered pixel nearest to the centroid whose 5x5 neighbourhood is all covered.
      let best = Infinity;
      const solid = (x: number, y: number) => {
        for (let dy = -2; dy <= 2; dy++)
          for (let dx = -2; dx <= 2; dx++) {
            const xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= width || yy >= height || data[4 * (yy * width + xx) + 3] < 250) return false;
          }
        return true;
      };
      for (let y = 0; y < height; y += 2)
        for (let x = 0; x < width; x += 2) {
          const d = (x - cx) ** 2 + (y - cy) ** 2;
          if (d < best && solid(x, y)) [best, meshPoint] = [d, { x, y }];
        }
      if (meshPoint) {
        const scale = canvas.clientWidth / width;
        meshPoint = { x: meshPoint.x * scale, y: meshPoint.y * scale };
      }
    }
    const mean = covered ? lumSum / covered : 0;
    return {
      width,
      height,
      covered,
      coveredFraction: covered / (width * height),
      meanLuminance: mean,
      luminanceStd: covered ? Math.sqrt(Math.max(0, lumSq / covered - mean * mean)) : 0,
      saturatedFraction: covered ? saturated / covered : 0,
      hueBins: bins.filter((n) => saturated > 0 && n >= 0.005 * covered).length,
      meshPoint,
      thumb,
    };
  });
}

/**
 * Mean absolute difference (0..255 per channel) between two frames' thumbnails, over the cells
 * where either frame has drawn something (so the empty background does not dilute it).
 */
export function frameDifference(a: PixelStats, b: PixelStats): number {
  let sum = 0;
  let cells = 0;
  for (let c = 0; c < a.thumb.length; c += 3) {
    const drawn = (t: number[]) => t[c] + t[c + 1] + t[c + 2] > 3;
    if (!drawn(a.thumb) && !drawn(b.thumb)) continue;
    cells++;
    for (let k = 0; k < 3; k++) sum += Math.abs(a.thumb[c + k] - b.thumb[c + k]);
  }
  return cells ? sum / (3 * cells) : 0;
}

/** The largest difference (0..255, mean over RGB) between two frames' thumbnails in any one cell: a local change. */
export function maxCellDifference(a: PixelStats, b: PixelStats): number {
  let max = 0;
  for (let c = 0; c < a.thumb.length; c += 3) {
    let d = 0;
    for (let k = 0; k < 3; k++) d += Math.abs(a.thumb[c + k] - b.thumb[c + k]);
    max = Math.max(max, d / 3);
  }
  return max;
}

/** Clicks the drawn geometry near its middle (the page treats a press-release without drag as a pick). */
export async function clickMesh(page: Page, stats: PixelStats): Promise<void> {
  expect(stats.meshPoint, 'no mesh pixels to click on').not.toBeNull();
  const box = await page.getByTestId('viewport-canvas').boundingBox();
  expect(box).not.toBeNull();
  await page.mouse.click(box!.x + stats.meshPoint!.x, box!.y + stats.meshPoint!.y);
}

/** Colour classes of the stage-1 layers, by hue (degrees), for clearly coloured pixels only. */
export const LAYER_HUES = {
  red: [[345, 360], [0, 12]],
  orange: [[22, 40]],
  yellow: [[42, 62]],
  lime: [[80, 135]],
  cyan: [[175, 200]],
  blue: [[205, 235]],
  purple: [[255, 300]],
} as const satisfies Record<string, ReadonlyArray<readonly [number, number]>>;
export type LayerHue = keyof typeof LAYER_HUES;

/**
 * Number of canvas pixels in each colour class: HSV saturation >= `minSaturation` and value >= 0.3
 * (the dimmed colormap and dimmed layers are greyish and stay below the saturation bound).
 */
export async function colorCensus(page: Page, minSaturation = 0.6): Promise<Record<LayerHue, number>> {
  const { counts } = await hueCensus(page, LAYER_HUES as unknown as Record<string, [number, number][]>, { minSaturation, minAlpha: 250 / 255 });
  return counts as Record<LayerHue, number>;
}

export interface HueCensus {
  /** Pixels per named hue range (HSV saturation >= minSaturation, value >= 0.3, alpha >= minAlpha). */
  counts: Record<string, number>;
  /** Pixels drawn see-through: 0.04 < alpha < 0.9 (a translucent surface over the empty background). */
  translucent: number;
  /** Pixels drawn opaque (alpha >= 0.98). */
  opaque: number;
}

/**
 * Counts canvas pixels in hue ranges (degrees, [lo, hi) pairs per name), for layers of any colour;
 * also counts translucent and opaque pixels.
 */
export async function hueCensus(
  page: Page,
  hues: Record<string, ReadonlyArray<readonly [number, number]>>,
  { minSaturation = 0.5, minAlpha = 0.5 } = {},
): Promise<HueCensus> {
  return page.evaluate(
    ({ hues, minSaturation, minAlpha }) => {
      const canvas = document.querySelector<HTMLCanvasElement>('[data-testid="viewport-canvas"]');
      if (!canvas) throw new Error('no canvas');
      const copy = document.createElement('canvas');
      copy.width = canvas.width;
      copy.height = canvas.height;
      const ctx = copy.getContext('2d', { willReadFrequently: true })!;
      ctx.drawImage(canvas, 0, 0);
      const data = ctx.getImageData(0, 0, copy.width, copy.height).data;
      const names = Object.keys(hues);
      const counts: Record<string, number> = Object.fromEntries(names.map((n) => [n, 0]));
      let translucent = 0;
      let opaque = 0;
      for (let i = 0; i < data.length; i += 4) {
        const a = data[i + 3] / 255;
        if (a > 0.04 && a < 0.9) translucent++;
        if (a >= 0.98) opaque++;
        if (a < minAlpha) continue;
        const r = data[i] / 255, g = data[i + 1] / 255, b = data[i + 2] / 255;
        const max = Math.max(r, g, b), min = Math.min(r, g, b);
        if (max < 0.3 || (max - min) / max < minSaturation) continue;
        const d = max - min;
        let h = max === r ? (g - b) / d : max === g ? 2 + (b - r) / d : 4 + (r - g) / d;
        h = ((h * 60) % 360 + 360) % 360;
        for (const name of names) if (hues[name].some(([lo, hi]) => h >= lo && h < hi)) counts[name]++;
      }
      return { counts, translucent, opaque };
    },
    { hues: hues as unknown as Record<string, number[][]>, minSaturation, minAlpha },
  );
}
