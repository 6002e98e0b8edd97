// layout_probe.js — the layout test's measurement, run inside the page (layout_test.js adds it with
// addScriptTag): window.layoutProbe.measure() returns { controls (how many), overlaps, outside
// (one line each), scrollWidth, viewWidth } of the page as laid out now. Lengths in CSS px.
//
// The controls: every visible input (not type=hidden), select, button, textarea, label, summary,
// canvas, outermost svg, table header cell (th: a readout's name), list item (li: the criteria, the
// ruler's events) and every element with a data-testid (the readouts, status and error lines of the
// test contract, docs/explorer.md); elements inside an svg are its drawing, not controls. A
// control's boxes are its border boxes (getClientRects: one per line of an inline element), the
// boxes of the text inside it (so a label whose text runs out of its box counts where the text is)
// and, for a list item whose marker stands outside it, the marker's ("3. ", "• ": its width in the
// item's font, left of the item's first line), each clipped to every ancestor that clips its
// overflow (a scrolled box shows only what lies inside it).
// overlaps: two controls whose boxes intersect with an area > 0 (each side longer than 1/128 px,
// below Chromium's layout unit of 1/64 px: float noise is not an overlap), unless one contains the
// other in the document (a control and its descendants) or one is the other's label (label.control).
// outside: visible elements whose clipped box reaches left of 0 or right of viewWidth
// (document.documentElement.clientWidth: the viewport less a vertical scrollbar), by more than
// 1/128 px; an element inside one already listed is not listed.
'use strict';
{
  const EPS = 1 / 128;
  const SELECTOR = 'input:not([type=hidden]), select, button, textarea, label, summary, canvas, svg, th, li, [data-testid]';
  const inSvg = (el) => el.parentElement !== null && el.parentElement.closest('svg') !== null;
  const visible = (el) => el.checkVisibility({ checkOpacity: false, checkVisibilityCSS: true });
  const measureText = document.createElement('canvas').getContext('2d');

  // An element as a failure names it: tag#id[data-testid=...] "its text".
  function nameOf(el) {
    let s = el.tagName.toLowerCase();
    if (el.id) s += '#' + el.id;
    if (el.dataset && el.dataset.testid) s += '[data-testid=' + el.dataset.testid + ']';
    const text = (el.textContent || el.value || '').trim().replace(/\s+/g, ' ').slice(0, 24);
    return text ? s + ' "' + text + '"' : s;
  }

  // The rectangle r cut to every ancestor of el that clips its overflow (its padding box); null
  // when nothing of it is left.
  function clip(el, r) {
    let { left, top, right, bottom } = r;
    for (let a = el.parentElement; a && a !== document.documentElement; a = a.parentElement) {
      const cs = getComputedStyle(a);
      if (cs.overflowX === 'visible' && cs.overflowY === 'visible') continue;
      const b = a.getBoundingClientRect();
      left = Math.max(left, b.left + a.clientLeft); right = Math.min(right, b.left + a.clientLeft + a.clientWidth);
      top = Math.max(top, b.top + a.clientTop); bottom = Math.min(bottom, b.top + a.clientTop + a.clientHeight);
    }
    return right - left > EPS && bottom - top > EPS ? { left, top, right, bottom } : null;
  }

  // The marker of a list item drawn outside its box ("N. " or "• "), left of its first line; null
  // for any other element.
  function markerBox(el, first) {
    const cs = getComputedStyle(el);
    if (el.tagName !== 'LI' || cs.listStylePosition !== 'outside' || cs.listStyleType === 'none') return null;
    const index = Array.prototype.indexOf.call(el.parentElement.children, el) + 1;
    measureText.font = cs.font;
    const width = measureText.measureText(cs.listStyleType === 'decimal' ? index + '. ' : '\u2022 ').width;
    const line = parseFloat(cs.lineHeight), height = Number.isFinite(line) ? line : 1.2 * parseFloat(cs.fontSize);
    return { left: first.left - width, top: first.top, right: first.left, bottom: Math.min(first.bottom, first.top + height) };
  }

  // A control's clipped boxes: border boxes, its text's boxes, an outside marker's.
  function boxesOf(el) {
    const rects = Array.from(el.getClientRects());
    const marker = rects.length > 0 ? markerBox(el, rects[0]) : null;
    if (marker) rects.push(marker);
    const walker = document.createTreeWalker(el, NodeFilter.SHOW_TEXT);
    const range = document.createRange();
    for (let t = walker.nextNode(); t; t = walker.nextNode()) {
      if (t.textContent.trim() === '' || !visible(t.parentElement)) continue;
      range.selectNodeContents(t);
      rects.push(...range.getClientRects());
    }
    return rects.map((r) => clip(el, r)).filter((r) => r !== null);
  }

  function controls() {
    const list = [];
    for (const el of document.body.querySelectorAll(SELECTOR)) {
      if (inSvg(el) || !visible(el)) continue;
      const boxes = boxesOf(el);
      if (boxes.length > 0) list.push({ el, boxes });
    }
    return list;
  }

  const related = (a, b) => a.contains(b) || b.contains(a) || (a.control && a.control === b) || (b.control && b.control === a);

  // The largest intersection of a box of a with a box of b (w, h, x, y), or null.
  function worstIntersection(a, b) {
    let worst = null;
    for (const p of a.boxes) {
      for (const q of b.boxes) {
        const w = Math.min(p.right, q.right) - Math.max(p.left, q.left), h = Math.min(p.bottom, q.bottom) - Math.max(p.top, q.top);
        if (w > EPS && h > EPS && (!worst || w * h > worst.w * worst.h)) worst = { w, h, x: Math.max(p.left, q.left), y: Math.max(p.top, q.top) };
      }
    }
    return worst;
  }

  function overlaps(list) {
    const found = [];
    for (let i = 0; i < list.length; ++i) {
      for (let j = i + 1; j < list.length; ++j) {
        if (related(list[i].el, list[j].el)) continue;
        const w = worstIntersection(list[i], list[j]);
        if (w) {
          found.push(nameOf(list[i].el) + ' and ' + nameOf(list[j].el) + ' overlap by ' + w.w.toFixed(1) + ' x ' + w.h.toFixed(1) +
            ' px at (' + w.x.toFixed(0) + ', ' + (w.y + window.scrollY).toFixed(0) + ') of the page');
        }
      }
    }
    return found;
  }

  function outside(viewWidth) {
    const found = [], listed = [];
    for (const el of document.body.querySelectorAll('*')) {
      if (inSvg(el) || !visible(el) || listed.some((l) => l.contains(el))) continue;
      const r = Array.from(el.getClientRects()).map((x) => clip(el, x)).find((x) => x !== null && (x.left < -EPS || x.right > viewWidth + EPS));
      if (r) {
        found.push(nameOf(el) + ' spans x = ' + r.left.toFixed(1) + ' .. ' + r.right.toFixed(1) + ', the viewport 0 .. ' + viewWidth);
        listed.push(el);
      }
    }
    return found;
  }

  function measure() {
    const viewWidth = document.documentElement.clientWidth, list = controls();
    return { controls: list.length, overlaps: overlaps(list), outside: outside(viewWidth),
      scrollWidth: document.documentElement.scrollWidth, viewWidth };
  }

  window.layoutProbe = { measure };
}
