// The bench's picture: reconstruction error against seconds (log scale), one point per mesh and method,
// one colour per method. Plain SVG text, written by hand (no plotting dependency).

export interface PlotPoint {
  method: string;
  mesh: string;
  seconds: number;
  error: number;
}

const WIDTH = 760;
const HEIGHT = 480;
const MARGIN = { left: 70, right: 150, top: 40, bottom: 56 };
const COLOURS = ['#1f77b4', '#ff7f0e', '#2ca02c', '#9467bd', '#d62728', '#8c564b'];

function escape(text: string): string {
  return text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
}

/** Short tick labels: 0.01, 0.1, 1, 10, 100, 1000, 1e+4. */
function label(x: number): string {
  return String(Number(x.toPrecision(3)));
}

/** About five round steps (1, 2 or 5 times a power of ten) from 0 to at least max. */
function linearTicks(max: number): number[] {
  const raw = max / 5;
  const power = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw) ?? 10 * power;
  const ticks: number[] = [];
  for (let k = 0; k * step < max + step * 1e-9; k++) ticks.push(k * step);
  if (ticks[ticks.length - 1] < max) ticks.push(ticks.length * step);
  return ticks;
}

/**
 * The SVG document. `methods` fixes the colours and the legend's order (methods without points still
 * get a legend entry, marked "no points"); `title` goes above the plot.
 */
export function errorVsSecondsSvg(points: PlotPoint[], methods: readonly string[], title: string): string {
  const plotW = WIDTH - MARGIN.left - MARGIN.right;
  const plotH = HEIGHT - MARGIN.top - MARGIN.bottom;
  const valid = points.filter((p) => p.seconds > 0 && Number.isFinite(p.seconds) && Number.isFinite(p.error));

  // x: whole decades around the data; y: from 0 to a round number above the largest error.
  const logs = valid.map((p) => Math.log10(p.seconds));
  let lo = logs.length ? Math.floor(Math.min(...logs)) : -1;
  let hi = logs.length ? Math.ceil(Math.max(...logs)) : 2;
  if (hi === lo) { lo -= 1; hi += 1; }
  const yTicks = linearTicks(Math.max(...valid.map((p) => p.error), 1e-12));
  const yMax = yTicks[yTicks.length - 1];
  const x = (seconds: number) => MARGIN.left + ((Math.log10(seconds) - lo) / (hi - lo)) * plotW;
  const y = (error: number) => MARGIN.top + plotH - (error / yMax) * plotH;

  const out: string[] = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${WIDTH}" height="${HEIGHT}" viewBox="0 0 ${WIDTH} ${HEIGHT}" font-family="sans-serif" font-size="12">`,
    `<rect width="${WIDTH}" height="${HEIGHT}" fill="white"/>`,
    `<text x="${MARGIN.left + plotW / 2}" y="22" text-anchor="middle" font-size="14">${escape(title)}</text>`,
  ];
  // Grid and ticks: every decade labelled, 2..9 as light minor lines.
  for (let d = lo; d <= hi; d++) {
    const px = x(10 ** d);
    out.push(`<line x1="${px}" y1="${MARGIN.top}" x2="${px}" y2="${MARGIN.top + plotH}" stroke="#ccc"/>`);
    out.push(`<text x="${px}" y="${MARGIN.top + plotH + 18}" text-anchor="middle">${label(10 ** d)}</text>`);
    if (d < hi) {
      for (let m = 2; m <= 9; m++) {
        const mx = x(m * 10 ** d);
        out.push(`<line x1="${mx}" y1="${MARGIN.top}" x2="${mx}" y2="${MARGIN.top + plotH}" stroke="#eee"/>`);
      }
    }
  }
  for (const t of yTicks) {
    const py = y(t);
    out.push(`<line x1="${MARGIN.left}" y1="${py}" x2="${MARGIN.left + plotW}" y2="${py}" stroke="#ccc"/>`);
    out.push(`<text x="${MARGIN.left - 8}" y="${py + 4}" text-anchor="end">${label(t)}</text>`);
  }
  out.push(`<rect x="${MARGIN.left}" y="${MARGIN.top}" width="${plotW}" height="${plotH}" fill="none" stroke="#333"/>`);
  out.push(`<text x="${MARGIN.left + plotW / 2}" y="${HEIGHT - 14}" text-anchor="middle">seconds (log scale, one thread)</text>`);
  out.push(`<text transform="translate(18 ${MARGIN.top + plotH / 2}) rotate(-90)" text-anchor="middle">reconstruction error (×1e3)</text>`);

  methods.forEach((method, i) => {
    const colour = COLOURS[i % COLOURS.length];
    const mine = valid.filter((p) => p.method === method);
    for (const p of mine) {
      out.push(`<circle cx="${x(p.seconds).toFixed(1)}" cy="${y(p.error).toFixed(1)}" r="4.5" fill="${colour}" fill-opacity="0.8" stroke="white">`
        + `<title>${escape(`${p.mesh}, ${method}: ${label(p.seconds)} s, error ${label(p.error)}`)}</title></circle>`);
    }
    const ly = MARGIN.top + 10 + i * 22;
    const lx = MARGIN.left + plotW + 16;
    out.push(`<circle cx="${lx}" cy="${ly}" r="5" fill="${colour}"/>`);
    out.push(`<text x="${lx + 12}" y="${ly + 4}">${escape(mine.length ? method : `${method} (no points)`)}</text>`);
  });
  out.push('</svg>');
  return `${out.join('\n')}\n`;
}
