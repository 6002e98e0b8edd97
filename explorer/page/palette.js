// palette.js — the colours of the design map's node counts: a count scale on d3-scale-chromatic's
// viridis (a sequential scheme, perceptually uniform and readable with the common colour-vision
// deficiencies; d3's files are copied into web/ by the build, so the page needs no network).
// X.countPalette(counts, shown) returns colour(count) for the counts present (no -1) and the
// legend's shown counts (sorted, a subset of counts):
//  - the shown counts sit at evenly spaced positions of the scheme, from MARGIN to 1 - MARGIN, so
//    that counts next to each other in the legend are at least (1 - 2 MARGIN) / 7 apart: on
//    viridis, a CIEDE2000 difference of at least 12 between any two such positions (measured
//    over the whole scheme; the page test checks >= 10 on the rendered legend);
//  - every other count is placed linearly by its value between the shown counts around it (the
//    lowest and highest counts at 0 and 1 when not shown): the colour grows with the count;
//  - -1 (no train) is grey, off the scale.
'use strict';
{
  const X = window.Explorer;
  const MARGIN = 0.08;
  const NO_TRAIN = '#c9ccd1';

  function countPalette(counts, shown) {
    const sorted = Array.from(new Set(counts)).filter((c) => c >= 0).sort((a, b) => a - b);
    const anchors = shown.filter((c) => c >= 0).map((c, k, all) =>
      [c, all.length === 1 ? 0.5 : MARGIN + (1 - 2 * MARGIN) * k / (all.length - 1)]);
    if (sorted.length && (!anchors.length || sorted[0] < anchors[0][0])) anchors.unshift([sorted[0], 0]);
    const top = sorted[sorted.length - 1];
    if (sorted.length && top > anchors[anchors.length - 1][0]) anchors.push([top, 1]);
    const position = (count) => {
      let k = 0;
      while (k + 1 < anchors.length && anchors[k + 1][0] <= count) ++k;
      if (k + 1 === anchors.length) return anchors[k][1];
      const [c0, t0] = anchors[k], [c1, t1] = anchors[k + 1];
      return t0 + (t1 - t0) * (count - c0) / (c1 - c0);
    };
    const colours = new Map(sorted.map((c) => [c, d3.interpolateViridis(position(c))]));
    return (count) => colours.get(count) || NO_TRAIN;
  }

  X.countPalette = countPalette;
}
