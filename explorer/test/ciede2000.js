// ciede2000.js — the colour difference CIEDE2000 of two sRGB colours, for the page test's palette
// check (page_test.js). Written from the published definition: G. Sharma, W. Wu, E. N. Dalal,
// "The CIEDE2000 color-difference formula: implementation notes, supplementary test data, and
// mathematical observations", Color Research & Application 30(1), 2005, Eqs. (1)-(22), with
// kL = kC = kH = 1. sRGB to CIELAB by IEC 61966-2-1 (the sRGB transfer curve and matrix) and the
// CIE 1976 L*a*b* formulas with the D65 white.
//   deltaE00([L1, a1, b1], [L2, a2, b2])   the difference of two CIELAB colours
//   labOfRgb([r, g, b])                      CIELAB of an 8-bit sRGB colour
//   SELF_CHECK                               pairs of the paper's Table 1 with their published values
'use strict';

const deg = Math.PI / 180;

function deltaE00([L1, a1, b1], [L2, a2, b2]) {
  const C1 = Math.hypot(a1, b1), C2 = Math.hypot(a2, b2);
  const Cbar7 = ((C1 + C2) / 2) ** 7;
  const G = 0.5 * (1 - Math.sqrt(Cbar7 / (Cbar7 + 25 ** 7)));  // Eq. (3)
  const ap1 = (1 + G) * a1, ap2 = (1 + G) * a2;                // Eq. (4)
  const Cp1 = Math.hypot(ap1, b1), Cp2 = Math.hypot(ap2, b2);  // Eq. (5)
  const hue = (b, ap) => (b === 0 && ap === 0 ? 0 : (Math.atan2(b, ap) / deg + 360) % 360);  // Eq. (6)
  const hp1 = hue(b1, ap1), hp2 = hue(b2, ap2);
  const dL = L2 - L1, dC = Cp2 - Cp1;                           // Eqs. (8), (9)
  let dh = 0;                                                   // Eq. (10)
  if (Cp1 * Cp2 !== 0) {
    dh = hp2 - hp1;
    if (dh > 180) dh -= 360;
    else if (dh < -180) dh += 360;
  }
  const dH = 2 * Math.sqrt(Cp1 * Cp2) * Math.sin(dh * deg / 2);  // Eq. (11)
  const Lbar = (L1 + L2) / 2, Cpbar = (Cp1 + Cp2) / 2;          // Eqs. (12), (13)
  let hbar = hp1 + hp2;                                         // Eq. (14)
  if (Cp1 * Cp2 !== 0) {
    if (Math.abs(hp1 - hp2) <= 180) hbar /= 2;
    else hbar = hbar < 360 ? (hbar + 360) / 2 : (hbar - 360) / 2;
  }
  const T = 1 - 0.17 * Math.cos((hbar - 30) * deg) + 0.24 * Math.cos(2 * hbar * deg) +
    0.32 * Math.cos((3 * hbar + 6) * deg) - 0.20 * Math.cos((4 * hbar - 63) * deg);  // Eq. (15)
  const dTheta = 30 * Math.exp(-(((hbar - 275) / 25) ** 2));    // Eq. (16)
  const RC = 2 * Math.sqrt(Cpbar ** 7 / (Cpbar ** 7 + 25 ** 7));  // Eq. (17)
  const SL = 1 + 0.015 * (Lbar - 50) ** 2 / Math.sqrt(20 + (Lbar - 50) ** 2);  // Eq. (18)
  const SC = 1 + 0.045 * Cpbar, SH = 1 + 0.015 * Cpbar * T;     // Eqs. (19), (20)
  const RT = -Math.sin(2 * dTheta * deg) * RC;                  // Eq. (21)
  const l = dL / SL, c = dC / SC, h = dH / SH;
  return Math.sqrt(l * l + c * c + h * h + RT * c * h);         // Eq. (22)
}

function labOfRgb(rgb) {
  const [r, g, b] = rgb.map((v) => {
    const c = v / 255;
    return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
  });
  const X = 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
  const Y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
  const Z = 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
  const f = (t) => (t > (6 / 29) ** 3 ? Math.cbrt(t) : t / (3 * (6 / 29) ** 2) + 4 / 29);
  const fx = f(X / 0.95047), fy = f(Y / 1.0), fz = f(Z / 1.08883);
  return [116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)];
}

// Sharma et al. 2005, Table 1: pairs 1, 7 and 17 (CIELAB) and their CIEDE2000 to four decimals.
const SELF_CHECK = [
  [[50, 2.6772, -79.7751], [50, 0, -82.7485], 2.0425],
  [[50, 0, 0], [50, -1, 2], 2.3669],
  [[50, 2.5, 0], [73, 25, -18], 27.1492],
];

module.exports = { deltaE00, labOfRgb, SELF_CHECK };
