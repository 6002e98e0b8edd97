// ruler.js — the a3 ruler at the current a2: the boundary events of `sphtroch boundaries` (one
// data-testid="event" line each, data-a3 its shortest round-trip text, data-kind), the node count
// between them, the current a3, and the list of events.
'use strict';
{
  const X = window.Explorer;
  const { $ } = X;
  const SVG_NS = 'http://www.w3.org/2000/svg';

  function svgElement(name, attrs, text) {
    const el = document.createElementNS(SVG_NS, name);
    for (const k in attrs) el.setAttribute(k, attrs[k]);
    if (text !== undefined) el.textContent = text;
    return el;
  }

  function renderRuler() {
    const svg = $('ruler'), list = $('events'), ruler = X.ruler;
    svg.textContent = '';
    list.textContent = '';
    if (!ruler || !X.result) return;
    const left = 20, right = 940;
    const x = (a3) => left + (right - left) * a3 / Math.PI;
    svg.appendChild(svgElement('line', { x1: left, y1: 50, x2: right, y2: 50, class: 'axis' }));
    const cuts = [0].concat(ruler.events.map((e) => e.a3), [Math.PI]);
    for (let i = 0; i + 1 < cuts.length && ruler.events.length > 0; ++i) {
      const count = i < ruler.events.length ? ruler.events[i].nodesBelow : ruler.events[i - 1].nodesAbove;
      const mid = (x(cuts[i]) + x(cuts[i + 1])) / 2;
      if (x(cuts[i + 1]) - x(cuts[i]) > 18) svg.appendChild(svgElement('text', { x: mid, y: 42, class: 'count' }, String(count)));
    }
    for (const e of ruler.events) {
      const line = svgElement('line', { x1: x(e.a3), y1: 30, x2: x(e.a3), y2: 70, class: 'event ' + e.kind,
        'data-testid': 'event', 'data-a3': e.text, 'data-kind': e.kind });
      line.appendChild(svgElement('title', {}, e.name + ': a3 = ' + e.text + ', nodes ' + e.nodesBelow + ' → ' + e.nodesAbove));
      svg.appendChild(line);
      const li = document.createElement('li');
      li.textContent = 'a3 = ' + e.text + '  ' + e.kind + '  nodes ' + e.nodesBelow + ' → ' + e.nodesAbove + '  (' + e.name + ')';
      list.appendChild(li);
    }
    svg.appendChild(svgElement('path', { d: 'M' + x(X.result.a3) + ' 74 l-6 10 h12 z', class: 'current' }));
    svg.appendChild(svgElement('text', { x: left, y: 86, class: 'tick' }, '0'));
    svg.appendChild(svgElement('text', { x: right - 8, y: 86, class: 'tick' }, 'π'));
    svg.appendChild(svgElement('text', { x: left, y: 16, class: 'tick' }, 'a3 → (node count between events)'));
  }

  X.renderRuler = renderRuler;
}
