// colors.js — the colour maps of the studio: part colours (golden-angle hues,
// as decomposition.ply uses), the deformation heat map (blue → green → red)
// and the four draft classes; each with what its colour bar shows.

export function partColor(part) {
  const hue = ((part * 137.508) % 360) / 60;
  const x = 1 - Math.abs((hue % 2) - 1);
  const [r, g, b] = [[1, x, 0], [x, 1, 0], [0, 1, x], [0, x, 1], [x, 0, 1], [1, 0, x]][Math.floor(hue) % 6];
  const level = (c) => (60 + 195 * c) / 255;
  return [level(r), level(g), level(b)];
}

export function heatColor(value) {
  const v = Math.min(1, Math.max(0, value));
  return [Math.min(1, Math.max(0, 2 * v - 0.5)), 1 - Math.abs(2 * v - 1), Math.min(1, Math.max(0, 1.5 - 2 * v))];
}

export const draftClasses = [
  { name: 'positive (releases along +d)', color: [0.30, 0.69, 0.31] },
  { name: 'negative (releases along −d)', color: [0.25, 0.47, 0.85] },
  { name: 'needs draft', color: [0.98, 0.80, 0.18] },
  { name: 'undercut', color: [0.86, 0.18, 0.18] },
];

export function cssColor([r, g, b]) {
  return `rgb(${Math.round(255 * r)},${Math.round(255 * g)},${Math.round(255 * b)})`;
}
