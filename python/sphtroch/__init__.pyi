"""sphtroch: trajectories of a point on the planet of a spherical planetary (bevel) gear train.

Angles are radians (float) or the command-line tool's text: "1.25", "pi/2", "2pi/3", "0.75pi",
"90deg"; a3 also "ap", "pi-ap", "a2", "pi-a2" with an optional offset ("ap+1e-6"). Gear ratios
n = p/q: int, fractions.Fraction, text ("5/2", "2.5") or a float that is a decimal of at most 9
places (2.5). Every bad argument raises InvalidInput naming it; flags (closed, pairs, literal,
velocity) accept only True or False (also numpy.bool_). Clinostat takes its speeds in rpm and
its angles in degrees, as `sphtroch clinostat`. Every computation runs with the GIL released;
GearTrain and Clinostat objects are immutable and may be shared between threads.
"""
import os
from fractions import Fraction
from typing import (Any, Callable, Dict, Iterator, List, Literal, NotRequired, Optional, Protocol, Sequence, Tuple, TypedDict,
                    Union, overload)

import numpy as np
import numpy.typing as npt

__version__: str

# What the runtime accepts, NumPy scalars included (mypy --strict: tests/python/typed_example.py).
Real = Union[float, int, np.floating[Any], np.integer[Any]]  # anything float() takes, not bool or str
Count = Union[int, np.integer[Any]]  # a whole number (__index__), not bool
Flag = Union[bool, np.bool_]
Angle = Union[Real, str]
RatioLike = Union[int, str, float, Fraction, np.integer[Any], np.floating[Any]]
AngleRange = Union[Tuple[Angle, Angle], str]  # (lo, hi), or the CLI's "LO:HI" text ("0:pi/2")
# A speed in rpm, read exactly: int, Fraction, text ("1.33", "4/3") or a float read as its repr ("1.33").
RpmLike = Union[int, str, float, Fraction, np.integer[Any], np.floating[Any]]
Point3 = Union[Tuple[Real, Real, Real], Sequence[Real], npt.NDArray[Any]]  # x, y, z

class ProgressBar(Protocol):
    """What progress= takes besides a function: a bar such as tqdm.tqdm(), told the work units as
    .total and the units done by .update(n) (typing only: not defined at runtime)."""

    total: Any
    def update(self, n: int) -> Any: ...

# progress=: a function progress(done, total) or a bar; called on the calling thread at most ten
# times a second and at the end (done == total); an exception it raises stops the call.
Progress = Union[Callable[[int, int], object], ProgressBar]

# The dicts the module returns, as the JSON the CLI writes (docs/cli.md): typing only (they are
# plain dicts at runtime; import them under `if typing.TYPE_CHECKING:` or in string annotations).
class Counts(TypedDict):
    nodes: int
    crossings: int
    tangencies: int
    cusps: int

class Inputs(TypedDict):
    a2: float
    a2_text: str
    a3: float
    a3_text: str
    literal: bool
    n: str
    n_value: float
    phase: float
    phase_reduced: float
    teeth: NotRequired[str]

class ConeAngles(TypedDict):
    a_p: float
    a_s: float

class Node(TypedDict):
    id: str
    position: List[float]
    longitude: float
    latitude: float
    params: List[float]
    branches: int
    kind: str
    angle: float
    crossing_pairs: int
    tangency_pairs: int

class Cusp(TypedDict):
    id: str
    position: List[float]
    param: float
    speed: float

class Nearest(TypedDict):
    kind: str
    name: str
    a2: float
    a3: float

class Margin(TypedDict):
    lower: float
    upper: float
    converged: bool
    nearest: Optional[Nearest]

# classify(): `sphtroch classify --json` (the functional form: one key, "class", is a Python keyword).
Classification = TypedDict("Classification", {
    "inputs": Inputs, "cone_angles": ConeAngles, "period": float, "class": str, "counts": Counts,
    "nodes": List[Node], "cusps": List[Cusp], "cusp_within_resolution": bool, "boundaries": Dict[str, Any],
    "analytic": Dict[str, Any], "censuses": Dict[str, Any], "certificate": Dict[str, Any],
    "agreement": Dict[str, Any], "certified": bool, "z_extremes": Dict[str, Any],
    "nearest_event": Optional[Dict[str, Any]], "margin": Margin, "dwell_points": List[Dict[str, Any]],
    "symmetry": Dict[str, Any], "tolerances": Dict[str, float], "work": Dict[str, Any]})

class ToleranceCensus(TypedDict):
    certified: bool
    nodes: int
    cusps: int

class ToleranceBoxWidths(TypedDict):
    a2: float
    a3: float
    phase: float

class PointTolerance(TypedDict):
    id: int
    position: List[float]
    max_displacement: Optional[float]
    d_da2: Optional[List[float]]
    d_da3: Optional[List[float]]
    d_dphase: List[float]

class MonteCarlo(TypedDict):
    samples: int
    seed: int
    same_census: int
    max_node_shift: float

class Tolerance(TypedDict):
    """tolerance(): `sphtroch tolerance --json`."""
    inputs: Dict[str, str]
    topology: Literal["holds", "changes", "undecided"]
    why: Optional[str]
    event: Optional[Dict[str, Any]]
    margin: Margin
    census: ToleranceCensus
    box: ToleranceBoxWidths
    nodes: List[PointTolerance]
    cusps: List[PointTolerance]
    monte_carlo: Optional[MonteCarlo]

class CertifiedMargin(TypedDict):
    lower: float
    upper: float

class PointsSolution(TypedDict):
    n: str
    teeth: NotRequired[str]
    a2: float
    a3: float
    phase: float
    axis: NotRequired[List[float]]
    frame: NotRequired[List[List[float]]]
    params: List[float]
    residual: float
    certified_margin: CertifiedMargin
    counts: Counts
    census_certified: bool
    isolated: bool

class PointsResult(TypedDict):
    """synth_points(): `sphtroch synth points --json`."""
    solutions: List[PointsSolution]
    teeth: NotRequired[str]  # with teeth=
    complete: bool
    undecided_boxes: int

class FitCandidate(TypedDict):
    n: str
    teeth: NotRequired[str]
    a2: float
    a3: float
    phase: float
    rms: float
    max_deviation: float
    margin: float
    certified_margin: CertifiedMargin
    counts: Counts
    census_certified: bool
    node_distance: NotRequired[float]

class FitResult(TypedDict):
    """fit(): `sphtroch synth fit --json`."""
    candidates: List[FitCandidate]
    teeth: NotRequired[str]  # with teeth=
    reason: str
    dropped: int

class Identified(TypedDict):
    """identify(): `sphtroch synth identify`."""
    n: str
    a2: float
    a3: float
    phase: float
    residual: float
    rms: float
    noise: float

class ClinostatTrainMap(TypedDict):
    """Clinostat.train_map: gravity(t) = rotation @ P(theta2_at_0 + theta2_rate * t), P the train's
    tracer (GearTrain.trace's Eq. 4); the keys of `sphtroch clinostat --json`'s "train" besides the train's own."""
    theta2_at_0: float
    theta2_rate: float
    rotation: npt.NDArray[np.float64]

class WorstWindowMean(TypedDict):
    """Clinostat.worst_window_mean(): `sphtroch clinostat --window W --json`'s "worst_window_mean"."""
    window_s: float
    lower: float
    upper: float
    start_s: float
    certified: bool

class TimeToEpsilon(TypedDict):
    """Clinostat.time_to(): `sphtroch clinostat --epsilon E --json`'s "time_to_epsilon"."""
    epsilon: float
    resolution_s: float
    first_s: Optional[float]
    stays_below_from_s: Optional[float]
    above_s: Optional[float]
    reason: str
    certified: bool

class CoverageSummary(TypedDict):
    """Clinostat.coverage_summary(): `sphtroch clinostat --coverage D --json`'s "coverage" but its
    "order" ("RING") and "dwell_s" (Clinostat.coverage())."""
    start_s: float
    duration_s: float
    nside: int
    fraction: float
    dwell_cv: float
    bound_s: float

class ClinostatReportTrain(TypedDict):
    """ClinostatReport's "train": the train (n as "p/q", a2, a3, phase in radians) and its map."""
    n: str
    a2: float
    a3: float
    phase: float
    theta2_at_0: float
    theta2_rate: float
    rotation: List[List[float]]

class ClinostatCoverage(TypedDict):
    """ClinostatReport's "coverage": CoverageSummary with "order" ("RING") and "dwell_s" (a list)."""
    start_s: float
    duration_s: float
    nside: int
    order: str
    fraction: float
    dwell_cv: float
    bound_s: float
    dwell_s: List[float]

class RunningMean(TypedDict):
    """One running mean of Clinostat.report(running_mean=...): the mean over [start_s, start_s + t_s]."""
    start_s: float
    t_s: float
    mean: List[float]
    magnitude: float

class WindowBandEnd(TypedDict):
    """One end of ClinostatReport's "window_band": the bracket [lower, upper] (g0) and a start
    time reaching it (for "min" its window's |mean| <= upper, for "max" >= lower)."""
    lower: float
    upper: float
    start_s: float

class WindowBand(TypedDict):
    """ClinostatReport's "window_band" (report(window=W, band=True), `--band`): the smallest and the
    largest |mean| over every window of W s, each bracket at most 1e-9 wide when "certified"; "bound"
    "torus" for a period too long to search (bounds over every pair of frame angles, not certified)."""
    window_s: float
    min: WindowBandEnd
    max: WindowBandEnd
    certified: bool
    bound: Literal["period", "torus"]

class WindowTarget(TypedDict):
    """ClinostatReport's "target" (report(..., target_g=G, tolerance=D)): whether every window
    mean's |mean| lies in [G - D, G + D]; None: not decided (the CLI exits 3). "start_s": a start
    whose window leaves the target (only when "inside" is False)."""
    g: float
    tolerance: float
    inside: Optional[bool]
    start_s: Optional[float]

class ClinostatReport(TypedDict):
    """Clinostat.report(): the object `sphtroch clinostat --json` prints (docs/clinostat.md)."""
    train: Optional[ClinostatReportTrain]
    train_note: NotRequired[str]
    averaged: str
    gravity_g0: NotRequired[float]
    period_s: Optional[float]
    mean_over_period: List[float]
    worst_window_mean: NotRequired[WorstWindowMean]
    window_band: NotRequired[WindowBand]
    target: NotRequired[WindowTarget]
    time_to_epsilon: NotRequired[TimeToEpsilon]
    running_mean: NotRequired[List[RunningMean]]
    coverage: NotRequired[ClinostatCoverage]

class ChainInfo(TypedDict):
    twists: List[float]
    rates: List[str]
    phases: List[float]
    period: float
    curve_period: float

class ChainCertificate(TypedDict):
    method: str
    why: str
    arcs: int
    arc_pairs: int
    boxes: int
    undecided: int
    cusp_resolution: float
    cusp_zone: float

ChainClassification = TypedDict("ChainClassification", {
    "chain": ChainInfo, "class": str, "certified": bool, "certificate": ChainCertificate, "counts": Counts,
    "nodes": List[Node], "cusps": List[Cusp]})

class UncertifiedResult(RuntimeError):
    """A node count the polyline census and the independent root-count census do not agree on,
    even after escalation (docs/cli.md: Certified counts; the tool's exit status 3). Raised by
    GearTrain.nodes(); classify() returns its dict with "certified": False instead.
    Attributes: .nodes (the polyline census's uncertified list), .polyline_nodes, .root_nodes."""

    nodes: List[Dict[str, Any]]
    """The polyline census's node list, uncertified."""
    polyline_nodes: int
    """Its node count."""
    root_nodes: int
    """The root-count census's node count."""

class InvalidInput(ValueError):
    """Bad input: .field (the argument), .value (as given), .valid (the valid range), .problem.
    str(e) reads "<field> = <value>: <problem>; valid: <valid>", on one line
    (newlines and other control characters escaped as the tool does: \\n, \\t, \\xHH)."""

    field: str
    """The argument: "a2", "a3", "n", "phase", "samples", "turns", "points", "grid", "closed", "literal", "max_work", ..."""
    value: str
    """The offending value as text."""
    problem: str
    """What is wrong with it."""
    valid: str
    """The valid range or forms."""

class GearTrain:
    """One spherical planetary gear train (Lin & Tsai 1990, Sec. 2): carrier twist a2, tracer
    twist a3 (both in (0, pi)), gear ratio n = p/q (p != 0), phase theta_p (Eq. 3).

    Immutable; picklable (the inputs are kept as exact text: pickling round-trips bit for bit).
    Raises InvalidInput (field "a2", "a3", "n", "teeth" or "phase") for a value out of range or
    malformed, or for both n and teeth (or neither).
    """

    @overload
    def __init__(self, a2: Angle, a3: Angle, n: RatioLike, phase: Angle = 0.0) -> None: ...
    @overload
    def __init__(self, a2: Angle, a3: Angle, *, phase: Angle = 0.0, teeth: str) -> None: ...
    @property
    def teeth(self) -> Optional[str]:
        """The tooth counts "ZS:ZP" (sun:planet; ZS < 0: internal gearing) when the train was made
        with teeth= instead of n (39:15 is kept, not reduced to 13:5: reports echo it next to n);
        None when it was made with n. Exactly one of n and teeth must be given."""
    @property
    def a2(self) -> float:
        """Carrier twist, radians."""
    @property
    def a3(self) -> float:
        """Tracer twist, radians (a cone reference plus its offset, rounded once)."""
    @property
    def n(self) -> float:
        """The gear ratio p/q as a float."""
    @property
    def ratio(self) -> str:
        """The gear ratio in lowest terms, "p/q" or "p"."""
    @property
    def p(self) -> int:
        """n = p/q in lowest terms: the numerator (it carries the sign of n)."""
    @property
    def q(self) -> int:
        """n = p/q in lowest terms: the denominator (>= 1)."""
    @property
    def phase(self) -> float:
        """The phase reduced to [-pi, pi], radians."""
    @property
    def planet_cone(self) -> float:
        """a_p = atan2(sin a2, cos a2 + n), radians."""
    @property
    def sun_cone(self) -> float:
        """a_s = a2 - a_p, radians."""
    @property
    def period(self) -> float:
        """2 pi q: the theta2 span after which the curve closes, radians."""
    @property
    def texts(self) -> Tuple[str, str, str, str]:
        """(a2, a3, n, phase) as text: as given, or the shortest round-trip form of a float."""
    @overload
    def trace(self, *, samples: Optional[Count] = None, turns: Optional[Real] = None,
              velocity: Literal[False] = False) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """The trajectory P(theta2) (Eq. 4): t (N,), P (N, 3) unit vectors, and with
        velocity=True V = dP/dtheta2 (N, 3) (Eq. 47a); float64, owned by the arrays (no copy).

        Closed curve (turns=None): t_i = 2 pi q i / N, i < N (the last point joins the first).
        Open curve: t_i = 2 pi K i / (N - 1), both ends included, K = turns in (0, 1e6].
        samples: 3 .. 10**7; default 360 (q + |p|) closed, 360 (1 + |n|) K + 1 open (as
        `sphtroch trace`). The same numbers as `sphtroch trace` prints.
        """
    @overload
    def trace(self, *, samples: Optional[Count] = None, turns: Optional[Real] = None,
              velocity: Literal[True]) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64],
                                                npt.NDArray[np.float64]]: ...
    def classify(self, *, literal: Flag = False, samples: Optional[Count] = None) -> Classification:
        """Nodes, cusps and the report's criteria: a dict with the keys and values of
        `sphtroch classify --json` (inputs, cone_angles, period, class, counts, nodes, cusps,
        boundaries, z_extremes, nearest_event, dwell_points, symmetry, criteria, censuses, agreement,
        certified, certificate, tolerances, work). "certified" is False when the censuses disagree (docs/cli.md: Certified counts).
        literal: analyse the doubles as given (no snapping onto boundaries within 1e-10 rad).
        samples: polyline census samples, 1024 .. 10**7 (default 256 (q + |p|)).
        """
    def nodes(self, *, literal: Flag = False, samples: Optional[Count] = None) -> List[Node]:
        """The "nodes" list of classify() (id "N1", "N2", ... as the plot labels them, position,
        longitude, latitude, params, branches, kind, angle, crossing_pairs, tangency_pairs), from the certified node census (without the
        criteria). Raises UncertifiedResult when the two censuses disagree after escalation."""
    def cusps(self, *, literal: Flag = False, samples: Optional[Count] = None) -> List[Cusp]:
        """The "cusps" list of classify() (id "C1", ..., position, param, speed)."""
    def svg(self, *, view: Union[str, Tuple[Angle, Angle], None] = None, size: Optional[Count] = None,
            labels: str = "auto", markers: str = "auto", style: str = "curve", literal: Flag = False,
            samples: Optional[Count] = None) -> str:
        """The curve on the sphere as SVG text, as `sphtroch plot` draws it (the certified census;
        an uncertified count says so in the caption). view: "auto" (the default: from the curve's
        mean direction, or a principal axis when that shows clearly more of it in front; the
        picture states the view), "top" (along the sun axis), "front", "side", "AZ,EL" or (az, el)
        angles; size: 64 .. 8192 px (default 520: the width; notes and caption below the sphere);
        labels: "auto" (every two labels one em apart; the picture says how many it shows), "numbers" (every N<i>, C<j>: the rows of nodes() then
        cusps()) or "none"; markers: "auto" (every node and cusp marker up to 200 of them, none
        above; the picture says how many it hides), "all" or "none"; style: "curve" (lines, back
        half dashed) or "density" (the time spent per steradian on the front half, for dense
        curves, as `sphtroch plot --style density`)."""
    def _repr_svg_(self) -> str:
        """Jupyter's picture of the train, bounded in time and never raising: svg() with its
        defaults (labels "auto", so a dense curve stays readable) when the census is cheap by the
        library's cost estimates: at most 2000 node points |p| (|p| + q) and (|p| + q)^3 <= 1.5e5
        (13/5, 40/9; well under 0.1 s). Otherwise the curve alone (no markers, at most 8000
        samples), its caption saying the census was not run and that .svg() runs it (or that it
        is beyond the census bound, as for n = 1333/2000). An error is drawn as a small SVG with
        its one-line message."""
    def kinematics(self, t: npt.ArrayLike) -> Dict[str, npt.NDArray[np.float64]]:
        """How the tracer moves at the carrier angles t (N,), per unit carrier rate, as `sphtroch
        trace --kinematics`: {"speed": |dP/dtheta2| (= |omega x P|, Eq. 47a), "geodesic_curvature":
        det(P, V, A)/|V|^3, "tangential_acceleration": d|V|/dtheta2}, float64 (N,). At a cusp the
        speed is 0, and the curvature and tangential acceleration, undefined there, are reported as 0.
        classify()["dwell_points"] lists the speed minima of a period. Raises InvalidInput("t")
        unless t is a 1-D array of finite numbers with |t| <= 2 pi 1e6."""
    def report(self, *, literal: Flag = False, samples: Optional[Count] = None) -> str:
        """The text report `sphtroch classify` prints for this train (the same bytes): counts, the
        certificate, nodes and cusps, the report's criteria with their margins, the nearest
        boundary event. classify() is the same analysis as a dict."""
    def node_set(self, *, literal: Flag = False, samples: Optional[Count] = None) -> "PointSet":
        """The nodes of nodes() as NumPy arrays (a PointSet: positions (k, 3), params (k, m), kinds,
        branches, longitude, latitude, ids 1..k = the plot's labels N1..Nk). Raises UncertifiedResult
        as nodes() does."""
    def cusp_set(self, *, literal: Flag = False, samples: Optional[Count] = None) -> "PointSet":
        """The cusps of cusps() as NumPy arrays (a PointSet: params (k, 1), kinds "cusp", branches 1)."""
    def plot(self, ax: Any = None, *, view: str = "top", samples: Optional[Count] = None,
             literal: Flag = False) -> Tuple[Any, Any]:
        """The curve in Matplotlib (imported only here): (fig, ax), drawn into `ax` if given. view
        "top", "front", "side": orthographic (as `sphtroch plot --view`), near half solid, far half
        dotted, the unit circle as outline; "lonlat": longitude/latitude in degrees, the curve
        broken where it wraps. Nodes red dots, cusps black crosses (node_set(), cusp_set()). samples:
        the curve's samples, as trace(samples=...)."""
    def classify_roots(self, *, literal: Flag = False) -> Dict[str, Any]:
        """The class by the root-count census alone (Eigen only, about 12x cheaper than classify()):
        a2, a3 (as analysed), boundaries, class, nodes, crossings, tangencies, cusps,
        analytic_nodes (the report's count for n = 1, 2, else None), analytic_cusps,
        agrees_with_report, node_points (the same node dicts as classify()["nodes"]: position,
        longitude, latitude, params, branches, kind, angle, crossing_pairs, tangency_pairs)."""
    def margin(self) -> Margin:
        """The certified distance to a change of the node or cusp census (`sphtroch tolerance`'s
        "margin"): {"lower", "upper", "converged", "nearest": {"kind", "name", "a2", "a3"} or None}.
        The largest d such that no boundary of the design map (pitch cones, pole lines,
        self-tangency loci) meets the square [a2 - d, a2 + d] x [a3 - d, a3 + d] lies in
        [lower, upper], radians; upper - lower <= max(1e-9, 1e-6 upper) when converged."""
    def tolerance(self, *, da2: Angle, da3: Angle, dphase: Angle = 0.0, samples: Optional[Count] = None,
                  seed: Count = 1, progress: Optional[Progress] = None) -> Tolerance:
        """`sphtroch tolerance --json` as a dict: will every train with a2, a3, phase within the
        half-widths (radians, or angle texts such as "0.1deg") draw this census? Keys topology
        ("holds", "changes", "undecided"), why, event, margin, census, box, nodes and cusps (each
        with position, max_displacement (proved, or None), d_da2, d_da3, d_dphase) and monte_carlo
        (with samples: that many random trains of the box classified, seeded; None without).
        progress: reported once per Monte Carlo train (see Progress). Raises InvalidInput for a
        negative or NaN half-width or a box leaving [1e-6, pi - 1e-6]."""
    def __eq__(self, other: object) -> bool:
        """Equal trains have the same doubles a2, a3, reduced phase (in [-pi, pi], -pi taken as pi),
        the same n = p/q, and a3 given the same way (a cone reference such as "ap" and its offset):
        GearTrain("60deg", 1.2, "13/5") == GearTrain("pi/3", 1.2, "13/5"). Texts are not compared."""
    def __hash__(self) -> int:
        """Consistent with ==: trains can key a dict or a set (memoising a sweep)."""
    def __reduce__(self) -> Any: ...

class Chain:
    """A gear-coupled rotation chain (docs/chains.md), as `sphtroch chain` reads it: k revolute
    joints (1 <= k <= 16) about intersecting axes, joint i turning N_i times as fast as one motor
    parameter s, each followed by a fixed twist; the tool axis traces
    P(s) = Rz(N1 s + P1) Rx(A1) Rz(N2 s + P2) Rx(A2) ... Rz(Nk s + Pk) Rx(Ak) z.

    twists: k angles in [0, pi] (radians or the angle text "pi/2"); rates: k exact rates (int,
    Fraction, text "-2/3" or "1.5", or a float that is a short decimal; 0 is a joint that does not
    turn; not all 0); phases: k angles, each joint's angle at s = 0 (default all 0). Each may also
    be the CLI's comma-separated text ("pi/2,1.2,0.4"). Chain(twists=[a2, a3], rates=[1, n],
    phases=[0, theta_p]) is GearTrain(a2, a3, n, phase=theta_p) (`train`).
    Immutable; picklable (the lists are kept as the CLI's text). Raises InvalidInput naming
    "twists", "rates" or "phases" (lists of different lengths, NaN, a twist outside [0, pi], a rate
    that is not exact, every rate 0, rates whose period exceeds the chain's bounds).
    """

    def __init__(self, twists: Union[Sequence[Angle], str], rates: Union[Sequence[RatioLike], str],
                 phases: Union[Sequence[Angle], str, None] = None) -> None: ...
    @staticmethod
    def from_urdf(path: Union[str, "os.PathLike[str]"], from_link: str, to_link: str,
                  axis: Optional[Sequence[float]] = None) -> "Chain":
        """The chain of a URDF robot description: the revolute joints on the path from from_link
        down to to_link, coupled to one motor by <mimic>, the tool axis `axis` (x, y, z) in
        to_link's frame (default (0, 0, 1)) — what `sphtroch chain classify --urdf PATH --from
        FROM --to TO [--axis X,Y,Z]` reads (docs/chains.md). Twists and phases as round-trip
        decimals (radians), rates exact. Raises InvalidInput naming the joint or link (field
        "urdf", "from", "to" or "axis"). Loads the part of the module that links urdfdom on first
        use."""
    def export_urdf(self, path: Union[str, "os.PathLike[str]", None] = None, *, name: str = "sphtroch_chain") -> str:
        """The chain as a URDF robot description, the bytes of `sphtroch chain export --urdf`:
        joint_1 ... joint_k, each joint after the first mimicking joint_1 with multiplier N_i / N_1;
        with a path also written there. from_urdf(path, "base_link", "tool") reads it back."""
    @property
    def twists(self) -> Tuple[float, ...]:
        """A1, ..., Ak, radians."""
    @property
    def rates(self) -> Tuple[str, ...]:
        """N1, ..., Nk in lowest terms, "p/q" or "p"."""
    @property
    def phases(self) -> Tuple[float, ...]:
        """P1, ..., Pk reduced to [-pi, pi], radians."""
    @property
    def period(self) -> float:
        """2 pi L / g: every joint is back after this s (L the lcm of the rates' denominators, g the
        gcd of the numerators of N_i L)."""
    @property
    def train(self) -> Optional[GearTrain]:
        """For k = 2 with both rates not 0, the gear train drawing the same curve: a2 = A1, a3 = A2,
        n = N2 / N1, phase = P2 - n P1 (its carrier angle theta2 = N1 s + P1); else None."""
    def __len__(self) -> int:
        """k, the number of joints."""
    @overload
    def trace(self, *, samples: Optional[Count] = None,
              velocity: Literal[False] = False) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
        """The curve over one period: s (N,) with s_i = period i / N, P (N, 3) unit vectors, and with
        velocity=True V = dP/ds = omega x P (N, 3); float64. samples: 3 .. 10**7, default
        360 sum |N_i| L / g (at most 10**6). The numbers `sphtroch chain trace` prints."""
    @overload
    def trace(self, *, samples: Optional[Count] = None,
              velocity: Literal[True]) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64],
                                                npt.NDArray[np.float64]]: ...
    def kinematics(self, t: npt.ArrayLike) -> Dict[str, npt.NDArray[np.float64]]:
        """How the tool axis moves at the motor parameters t (N,), per unit s, as `sphtroch chain
        trace --kinematics`: {"speed", "geodesic_curvature", "tangential_acceleration"}, float64
        (N,); 0 curvature and tangential acceleration at a cusp. Raises InvalidInput("t") unless t
        is a 1-D array of finite numbers with |t| <= period."""
    def classify(self) -> ChainClassification:
        """The certified census: a dict with the keys and values of `sphtroch chain classify
        --json` (chain, class, certified, certificate, counts, nodes, cusps; params are values of s).
        For k = 2 the gear train's census (classify's), checked by the chain census. "certified"
        is False when a box stayed undecided or the censuses disagree."""
    def nodes(self) -> List[Node]:
        """The "nodes" list of classify(). Raises UncertifiedResult (with .nodes) when the census is
        not certified (the CLI's exit status 3)."""
    def cusps(self) -> List[Cusp]:
        """The "cusps" list of classify() (id, position, param, speed)."""
    def report(self) -> str:
        """The text `sphtroch chain classify` prints for this chain (the same bytes)."""
    def svg(self, *, view: Union[str, Tuple[Angle, Angle], None] = None, size: Optional[Count] = None,
            labels: str = "auto", markers: str = "auto", style: str = "curve") -> str:
        """The curve on the sphere as SVG text, as `sphtroch chain plot` draws it (the same bytes):
        the nodes and cusps of classify(), the caption saying NOT CERTIFIED when the census is not.
        The options are GearTrain.svg's."""
    def boundaries(self, vary: str) -> Dict[str, Any]:
        """Where the census changes as one twist or phase varies: vary "NAME:LO:HI" (A2:0:pi, P3:0:1),
        the dict `sphtroch chain boundaries --vary VARY --json` prints (chain, vary, accuracy,
        uncovered, certified, why, note, events with value, kind, name, nodes_below, nodes_above,
        cusps_below, cusps_above, accuracy, and for the slab search bracket and root: certified,
        lo, hi, params). "certified" is False where the CLI exits 3. Raises
        InvalidInput("vary") for a bad range."""
    def __eq__(self, other: object) -> bool:
        """The same chain: equal twists, rates and reduced phases (as doubles and exact rates)."""
    def __hash__(self) -> int:
        """Consistent with ==."""
    def __reduce__(self) -> Any: ...

class Wrist:
    """A geared spherical wrist with 2 or 3 motors (docs/wrists.md), as `sphtroch wrist` reads it:
    k revolute joints (1 <= k <= 6) about intersecting axes, joint i at theta_i = sum_j C_ij u_j + P_i
    for motor angles u = (u_1, .., u_m), each joint followed by a fixed twist; the last body's frame
    F(u) = Rz(theta_1) Rx(A1) ... Rz(theta_k) Rx(Ak) and the tool axis P(u) = F(u) axis.

    twists: k angles in [0, pi] (radians or the angle text "pi/2"); coupling: k rows of m exact
    rates (int, Fraction, text "3/2", or a float that is a short decimal), rank m, m = 2 or 3;
    phases: k angles (default all 0); axis: the tool axis in the last body (default z; pointing
    only). Each may also be the CLI's text ("0,1,0.5", "1,0;0,1;0,3/2").
    Immutable; picklable (kept as the CLI's text). Raises InvalidInput naming "twists", "coupling",
    "phases" or "axis" as `sphtroch wrist` does (a rank-deficient coupling, rows != k, NaN, ...).
    """

    def __init__(self, twists: Union[Sequence[Angle], str], coupling: Union[Sequence[Sequence[RatioLike]], str],
                 phases: Union[Sequence[Angle], str, None] = None, axis: Union[Sequence[float], str, None] = None) -> None: ...
    @property
    def motors(self) -> int:
        """m, the number of motors (the coupling's columns)."""
    @property
    def periods(self) -> List[float]:
        """T_1, .., T_m: motor j's period 2 pi L_j, L_j the lcm of the denominators in column j."""
    def ik(self, target: Union[Sequence[float], str, None] = None, *,
           frame: Union[Sequence[float], Sequence[Sequence[float]], str, None] = None) -> Dict[str, Any]:
        """Every inverse-kinematics solution on the motor torus, each proved the only root in its
        box: the object `sphtroch wrist ik --json` prints ({"count", "certified", "solutions":
        [{"motors", "box_radius"}], "on_fold", "wrist", "target", ...}). target: a unit vector X,Y,Z
        to point the tool axis along (2 motors); frame: a unit quaternion w,x,y,z or a rotation
        matrix (9 numbers by rows, or 3 x 3) to hold (3 motors). "certified": False where the tool
        exits 3 (a target on a fold: a double root). Raises InvalidInput naming "target",
        "target-frame" or "coupling" (a problem too large, refused up front with its cost)."""
    def cap(self, home: Union[Sequence[float], str]) -> Dict[str, Any]:
        """The largest spherical cap about home with no fold inside (2 motors): the object
        `sphtroch wrist cap --json` prints ({"radius": {"lower", "upper", "width"}, "count",
        "certified", "home_on_fold", ...}; radians). Raises InvalidInput naming "home" or "coupling"."""
    def atlas(self, width: Optional[float] = None, sphere_cell: Optional[float] = None) -> Dict[str, Any]:
        """The fold curve of a 2-motor wrist and the regions it cuts out: the object `sphtroch wrist
        atlas --json` prints (the critical cells of the motor torus, every other cell proved
        fold-free, the fold polylines on the sphere, and the regions with their certified IK counts,
        areas, workspace and voids). width: the torus cells' size in radians of joint motion (0.001
        to 1; default 0.05); sphere_cell: the sphere grid's cell for the regions (0.003 to 0.5;
        default 0.02). Raises InvalidInput naming "width", "sphere-cell" or "coupling"."""

class PointSet:
    """Nodes or cusps of a train as NumPy arrays (GearTrain.node_set(), cusp_set()), row i the i-th
    dict of nodes() / cusps() (len(), [i] and iteration give those dicts). Radians.
    Attributes: kind ("nodes" or "cusps"); ids (k,) int64, 1..k (the plot's labels N1..Nk);
    positions (k, 3) float64 unit vectors; params (k, m) float64, the carrier angles theta2 of the
    branches through each point (m = the most branches; shorter rows padded with NaN; cusps m = 1);
    kinds (k,) str ("crossing", "tangency", ..., or "cusp"); branches (k,) int64; longitude,
    latitude (k,) float64 (atan2(y, x), asin(z))."""

    kind: str
    ids: npt.NDArray[np.int64]
    positions: npt.NDArray[np.float64]
    params: npt.NDArray[np.float64]
    kinds: npt.NDArray[np.str_]
    branches: npt.NDArray[np.int64]
    longitude: npt.NDArray[np.float64]
    latitude: npt.NDArray[np.float64]
    def __len__(self) -> int: ...
    def __getitem__(self, i: int) -> Dict[str, Any]: ...
    def __iter__(self) -> Iterator[Dict[str, Any]]: ...
    def to_list(self) -> List[Dict[str, Any]]:
        """The dicts of nodes() / cusps() (copies)."""
    def columns(self) -> Dict[str, npt.NDArray[Any]]:
        """1-D columns id, kind, x, y, z, longitude, latitude, branches, t1 .. tm: what
        pandas.DataFrame(...) takes."""
    def to_dataframe(self) -> Any:
        """pandas.DataFrame(columns()) (needs pandas, imported only here)."""

class Clinostat:
    """A two-axis clinostat or random positioning machine run at constant speeds, as `sphtroch
    clinostat` takes it: the gravity the sample feels, its means over time windows, the gear train
    whose tracer draws its path, where on the sphere it spends its time.

    Convention: lab Z up, gravity (0, 0, -1) in units of g0 = 9.80665 m/s^2; outer axis
    u = (sin tilt, 0, cos tilt); inner axis v = cos(frame_angle) u + sin(frame_angle) w,
    w = (-cos tilt, 0, sin tilt), carried by the outer frame; frame angles
    phi = phase + 2 pi rpm t / 60 (t in seconds); sample frame R(t) = Rot(u, phi_o) Rot(v, phi_i);
    the sample feels g_s = R^T (0, 0, -1).

    outer_rpm, inner_rpm: signed speeds read exactly as the CLI's --outer / --inner: an int, a
    Fraction, text ("1.33", "-2", "4/3": at most 6 decimal places, |rpm| <= 1000), or a float read
    as its repr (1.33 -> "1.33" -> 133/100 rpm; 1e-05 or 0.1 + 0.2 are refused: give the text or
    a Fraction). Not both 0. tilt (outer axis from the vertical), frame_angle (between the axes):
    degrees in [0, 180]; phase_outer, phase_inner: the frames' angles at t = 0, degrees,
    |phase| <= 1e6. offset: None (the centre) or the sample point (x, y, z) in metres, sample
    frame, |r| <= 10; with an offset, period, mean_over_period, window_mean, worst_window_mean and
    time_to are of the effective gravity R^T((0, 0, -1) - a / g0) there (as the CLI's averages),
    while the train and the coverage are of g_s. gravity_g0: the environment's gravity G in g0, (0,
    1000] (the CLI's --gravity, named apart from the method gravity(); default 1): the averages (period, mean_over_period, window_mean,
    worst_window_mean, time_to, report) are then of G g_s (with an offset, of R^T(G (0, 0, -1) -
    a / g0)); epsilon and the target stay in g0; gravity() stays the direction g_s.
    Immutable. Raises InvalidInput whose field is the CLI's option: "outer", "inner", "tilt",
    "frame-angle", "phase-outer", "phase-inner", "offset" or "gravity".
    """

    def __init__(self, outer_rpm: RpmLike, inner_rpm: RpmLike, *, tilt: Real = 90.0, frame_angle: Real = 90.0,
                 phase_outer: Real = 0.0, phase_inner: Real = 0.0, offset: Optional[Point3] = None,
                 gravity_g0: Real = 1.0) -> None: ...
    @property
    def outer_rpm(self) -> str:
        """The outer frame's exact speed as text: "1.33" when a decimal, else "p/q" ("4/3")."""
    @property
    def inner_rpm(self) -> str:
        """The inner frame's exact speed as text, as outer_rpm."""
    @property
    def tilt(self) -> float:
        """The outer axis from the vertical, degrees."""
    @property
    def frame_angle(self) -> float:
        """The angle between the axes, degrees."""
    @property
    def phase_outer(self) -> float:
        """The outer frame's angle at t = 0, degrees."""
    @property
    def phase_inner(self) -> float:
        """The inner frame's angle at t = 0, degrees."""
    @property
    def offset(self) -> Optional[Tuple[float, float, float]]:
        """The sample point (x, y, z), metres, or None when none was given."""
    @property
    def gravity_g0(self) -> float:
        """The environment's gravity G, units of g0 (1 unless given)."""
    @property
    def period(self) -> Optional[float]:
        """Seconds after which the averaged gravity repeats (both frames back where they started,
        from the exact speeds: 6000.0 for 1.33 and 2 rpm), or None when it does not move in the
        sample. `--json`'s "period_s"."""
    @property
    def mean_over_period(self) -> npt.NDArray[np.float64]:
        """The mean of the averaged gravity over a period (3,), units of g0 (resonances included:
        a harmonic of frequency exactly 0 is constant). `--json`'s "mean_over_period"."""
    @property
    def train(self) -> Optional[GearTrain]:
        """The spherical gear train whose tracer draws g_s: n = outer / inner (exact: 133/200 for
        1.33 and 2 rpm), a2 = frame angle, a3 = pi - tilt (radians), with its phase; `--json`'s
        "train" (n, a2, a3, phase). None for a machine whose path is a circle (a speed 0, parallel
        axes, a vertical outer axis) or beyond the train's limits: train_note says why."""
    @property
    def train_map(self) -> Optional[ClinostatTrainMap]:
        """How the train's tracer gives g_s: {"theta2_at_0", "theta2_rate" (rad/s), "rotation"
        (3, 3)}: gravity(t) = rotation @ P(theta2_at_0 + theta2_rate t). None without a train."""
    @property
    def train_note(self) -> str:
        """Why there is no train ("" when there is one): `--json`'s "train_note"."""
    def gravity(self, t: Union[Real, npt.ArrayLike]) -> npt.NDArray[np.float64]:
        """g_s = R(t)^T (0, 0, -1) at the times t (seconds, |t| <= 1e12): (N, 3) for t of shape (N,),
        (3,) for a scalar; float64, units of g0 (the CLI's --trace columns gx, gy, gz). The frame
        angles are reduced exactly (whole turns removed in integers), so t = 1e6 s keeps ~1e-15.
        Raises InvalidInput("t")."""
    def effective_gravity(self, t: Union[Real, npt.ArrayLike]) -> npt.NDArray[np.float64]:
        """The effective gravity R^T (G (0, 0, -1) - a / g0) of the sample point at the times t, a its
        acceleration, G the environment's gravity; shapes as gravity(). Equal to G gravity() without
        an offset."""
    def window_mean(self, t0: Real, window: Real) -> npt.NDArray[np.float64]:
        """The mean of the averaged gravity (the effective gravity with an offset, else g_s) over
        [t0, t0 + window] (3,), units of g0, in closed form (rounding ~1e-15). window: 0 .. 1e9 s
        (0: the value at t0); |t0| <= 1e12. Raises InvalidInput("t0" or "window")."""
    def worst_window_mean(self, window: Real) -> WorstWindowMean:
        """M(W): the largest |mean| of the averaged gravity over a window of W seconds, whatever
        time it starts, as a certified bracket, as `sphtroch clinostat --window W --json`:
        {"window_s", "lower", "upper" (M(W) in [lower, upper], upper - lower <= 1e-9), "start_s" (a
        start in [0, period) whose window mean is >= lower), "certified" (False: the bracket is
        wider, the tool's exit status 3)}. window: (0, 1e9]. Raises InvalidInput: "window";
        "outer" when the speeds' period is too long for the search."""
    def time_to(self, epsilon: Real, resolution: Real = 1.0) -> TimeToEpsilon:
        """How long to average before the mean is below epsilon whenever the experiment starts, as
        `sphtroch clinostat --epsilon E --resolution S --json`: windows W = S, 2S, ...;
        {"epsilon", "resolution_s", "first_s" (the shortest W with M(W) <= epsilon),
        "stays_below_from_s" (a multiple of S from which every longer window, of any real
        length, is below: M is not monotone), "above_s" (a length above epsilon within 2 S below
        it, or None), "reason" (why both are None, or why not certified), "certified"}. epsilon:
        [1e-12, 1e9] units of g0; resolution: (0, 1e6] s. Raises InvalidInput: "epsilon",
        "resolution" (also when the search would cover more than 10**6 windows), "outer"."""
    def coverage(self, duration: Real, nside: Count = 8, start: Real = 0.0) -> npt.NDArray[np.float64]:
        """Seconds g_s spends in each cell of the HEALPix grid of nside (RING order: healpy draws
        it as it is) over [start, start + duration]: float64 (12 nside^2,), `--coverage D --json`'s
        "dwell_s". Each cell's time is right within coverage_summary()'s bound_s. duration: (0, 1e12]
        s; nside: a power of two 1 .. 1024; |start| <= 1e12. Raises InvalidInput: "coverage" (also
        for a walk of more than 2e6 steps, and in a build without HEALPix), "nside", "start"."""
    def coverage_summary(self, duration: Real, nside: Count = 8, start: Real = 0.0) -> CoverageSummary:
        """The dwell map of coverage() summed up, as `--coverage D --json`'s "coverage": {"start_s",
        "duration_s", "nside", "fraction" (share of cells visited), "dwell_cv" (coefficient of
        variation of the dwell over all cells; 0 = uniform), "bound_s" (every cell's time is within
        it)}."""
    def report(self, *, window: Optional[Real] = None, epsilon: Optional[Real] = None, resolution: Optional[Real] = None,
               coverage: Optional[Real] = None, nside: Count = 8, start: Real = 0.0,
               running_mean: Optional[Sequence[Real]] = None, band: Flag = False, target_g: Optional[Real] = None,
               tolerance: Optional[Real] = None) -> ClinostatReport:
        """The whole report as the object `sphtroch clinostat --outer O --inner I ... --window W
        --epsilon E --resolution S --coverage D --nside K --start T --json` prints, member for member
        and double for double (machine/clinostat_report.hpp writes it for both): "train" (or None
        and "train_note"), "averaged", "period_s", "mean_over_period", and with window
        "worst_window_mean", with epsilon "time_to_epsilon", with running_mean (durations T, s)
        "running_mean" (the mean over [start, start + T] for each T, `--running-mean`), with
        coverage "coverage" (HEALPix), with band=True (needs window) "window_band" (the certified
        min and max of |window mean| over every start, `--band`), with target_g=G and tolerance=D
        (need band; finite, >= 0, g0) "target" (whether every window mean lies in G +- D). Ranges as
        worst_window_mean(), time_to() (resolution only with epsilon; default 1 s) and coverage().
        Raises InvalidInput as those do, naming the CLI's options."""
    def _repr_svg_(self) -> Optional[str]:
        """Jupyter's picture: the train's (GearTrain._repr_svg_), or None without a train (Jupyter
        then shows the repr)."""

def crossings(points: npt.ArrayLike, closed: Flag = True, *, pairs: Flag = False,
              max_crossings: Count = 10_000_000, max_work: Count = 50_000_000) -> Dict[str, Any]:
    """The exact self-crossings of a spherical polyline (edges are great-circle arcs; edge e
    joins row e to row e+1, and the last row to the first when closed), as `sphtroch crossings`.

    points: (N, 3) x, y, z rows (directions; need not be unit), of an integer or float dtype
    (strings, bool, complex, objects: InvalidInput). A C-contiguous float64 array is copied once
    (24 bytes per row) before it is validated, so another thread writing into it cannot change
    what is searched; anything else is converted once (input_converted is then True). Wrong
    shape, N too small, zero or non-finite rows, equal or antipodal consecutive rows:
    InvalidInput with field "points".

    closed, pairs: True or False (anything else: InvalidInput naming it). Without pairs only
    counts are kept (memory O(N)); pairs=True adds pairs (k, 2) int64 edge pairs i < j of both
    kinds sorted by (i, j) (the rows of `--pairs`, sorted), and kinds (k strings: "crossing",
    "touching", "overlap").
    max_crossings, max_work (0 .. 10**15): as `--max-crossings` / `--max-work`: more crossings
    + touchings, or more work (candidate edge pairs + overlapping box pairs, ~0.1 s per 10**6
    here; random points need about N**2), raise InvalidInput with that field.

    Returns: vertices, closed, crossings (count), touchings (count), [pairs, kinds],
    candidate_pairs, predicates, input_converted, timings {"seconds_search"}.
    """

def atlas(n: RatioLike, grid: Count = 128, a2: AngleRange = (0.0, 3.141592653589793),
          a3: AngleRange = (0.0, 3.141592653589793), threads: Optional[Count] = None,
          literal: Flag = False, *, progress: Optional[Progress] = None,
          svg: Flag = False) -> Dict[str, Any]:
    """The classification map over (a2, a3) for one gear ratio, as `sphtroch atlas`: G x G cells
    sampled at their centres (row i: a2, column j: a3). Arrays of shape (G, G): a2, a3 (float64,
    radians), nodes, crossings, tangencies, cusps, analytic_nodes (-1 where the report gives no
    count, n != 1, 2), analytic_cusps (int64), agree (int8: 1 agree, 0 disagree, -1 no
    prediction), cusps_agree (bool); plus n (str), threads (int), summary (str: the summary
    `sphtroch atlas` prints, with the wall time and the certificate: every class change between
    neighbouring cells crossed by a boundary of the boundary set), uncertified (str: "" or why the
    tool would exit with status 3) and, with svg=True, svg (str: the map `sphtroch atlas --svg`
    writes, the same bytes).
    grid: 1 .. 4096; ranges (lo, hi) or the CLI's "LO:HI" text, 0 <= lo < hi <= pi; threads: 1 .. 1024
    (default: all cores). progress(done, total) (or a tqdm bar: Progress) is called about every 100 ms
    (and at the end) with the cells done; Ctrl-C raises KeyboardInterrupt within ~0.1 s, and an exception progress raises stops
    the call (the cells being computed finish first: at most threads x 64 cells).
    """

def classify_a3_range(a2: Angle, n: RatioLike, a3: AngleRange, count: Count = 721,
                      literal: Flag = False) -> List[Dict[str, Any]]:
    """classify_roots at `count` evenly spaced a3 in [lo, hi] (both ends included), runs of equal
    (class, nodes, cusps) merged: a list of {a3_first, a3_last, samples, class, nodes, cusps}
    (radians). The class changes between the last sample of a run and the first of the next.
    a3: 0 <= lo < hi <= pi as for atlas; an end within 1e-6 of 0 or pi (where no train exists) is
    sampled 1e-6 inside. Raises InvalidInput: "a3" for another range,
    "count" unless 2 .. 10**6."""

def boundaries(n: RatioLike, a2: Angle) -> Dict[str, Any]:
    """Where the node count changes in a3 at one a2 (`sphtroch boundaries --n N --a2 A --json`,
    the same doubles): {"n", "n_value", "a2", "accuracy" (1e-12 rad), "events": [{"a3", "kind"
    ("pitch_cone", "pole", "tangency"), "name", "nodes_below", "nodes_above", "cusps_below",
    "cusps_above", "b", "m", "label"}]}, events by ascending a3 (m, label None except for
    tangencies). No bisection of classify_roots is needed: the events are refined to 1e-12 rad.
    Raises InvalidInput: "n" (0, or beyond the census cost bound), "a2" outside [1e-6, pi - 1e-6]."""

def boundary_loci(n: RatioLike, a2: AngleRange = (0.0, 3.141592653589793), steps: Count = 720,
                  threads: Optional[Count] = None, *,
                  progress: Optional[Progress] = None) -> List[Dict[str, Any]]:
    """The boundary curves of the (a2, a3) map over an a2 range (`sphtroch boundaries --a2 LO:HI`):
    a list of {"kind", "name", "m", "label", "a2", "a3", "b"} with a2, a3, b float64 arrays (radians)
    sampled at the cell centres lo + (hi - lo)(k + 1/2)/steps. steps: 1 .. 10000; threads: 1 .. 1024
    (default: all cores). progress(done, total) and Ctrl-C as for atlas (done: a2 samples)."""

def scene(scene: Union[str, Dict[str, Any]]) -> Dict[str, Any]:
    """Runs a scene (`sphtroch scene`'s JSON format, docs/cli.md; text or a dict) without touching a
    file: {"trains": [{"name", "outputs": {effect: text}, "uncertified", "explanation"}]}, each
    output the bytes `sphtroch scene` writes to that effect's path (the path only decides the
    classification's form: ".txt" text, else JSON); "uncertified" is "" or why the tool would exit
    with status 3; "explanation" is `--explain --json`'s object (stages run, their work).
    Raises InvalidInput naming "scene: <path in the scene>" as the tool does."""

def identify(t: npt.ArrayLike, points: npt.ArrayLike) -> Identified:
    """The gear train of a timed trace (as `sphtroch synth identify`): t (N,) carrier angles,
    points (N, 3) unit vectors over one period, dense enough that the planet turns by less than
    3pi/4 between two samples. Returns {"n": "p/q" (the simplest fraction that fits, |p|, q <=
    1000), "a2", "a3", "phase" (radians), "residual" (max |P(t_i) - P_i|), "rms", "noise"}.
    Raises InvalidInput naming "t", "points" or "samples"."""


def synth_points(points: npt.ArrayLike, *, n: Optional[RatioLike] = None,
                 ratios: Optional[Tuple[Count, Count]] = None, teeth: Optional[str] = None,
                 free_axis: Flag = False, threads: Optional[Count] = None,
                 progress: Optional[Progress] = None) -> PointsResult:
    """Every gear train of ratio n (or of every ratio of ratios=(P, Q), as `--ratios P,Q`;
    or teeth="ZS:ZP" (n = ZS/ZP) or "MIN..MAX" (every n = +-ZS/ZP with both counts in the range),
    as `--teeth`, each solution then echoing its "teeth")
    whose tracer passes through the three points (a (3, 3) array of
    unit vectors; fixed frame, sun axis Z), as `sphtroch synth points --json`: {"solutions": [{"n",
    "a2", "a3", "phase" (in [0, 2 pi / q)), "params" (theta2 at each point), "residual",
    "certified_margin": {"lower", "upper"} (radians in (a2, a3) to a change of the census, as
    GearTrain.margin()), "counts": {"nodes", "crossings", "tangencies", "cusps"}, "census_certified",
    "isolated"}], "complete" (the list is
    certified to hold every train), "undecided_boxes"}. With free_axis=True (`--free-axis`): five
    points (a (5, 3) array), the sun axis anywhere; each solution also has "axis" (the sun axis) and
    "frame" (the train's x, y, z axes in the points' coordinates), and the work bound is that of
    the CLI (sum of (|p| + q)^2 <= 500); threads (None: all cores) searches run at once.
    progress (a function progress(done, total) or a tqdm bar; Progress): told the ratios done,
    at most ten times a second and at the end; an exception it raises stops the call (after the
    ratio being searched).
    Raises InvalidInput naming "points", "n", "ratios", "teeth", "free_axis", "threads" or "progress"."""


def synth_points_text(points: npt.ArrayLike, *, n: Optional[RatioLike] = None,
                      ratios: Optional[Tuple[Count, Count]] = None, teeth: Optional[str] = None,
                      free_axis: Flag = False, threads: Optional[Count] = None,
                      progress: Optional[Progress] = None) -> str:
    """What synth_points computes, as the text `sphtroch synth points` prints (the same arguments,
    the same refusals): per ratio its train count and whether the list is certified complete, then
    each train with its angles, theta2 at the points, residual, census, certified margin and the
    command that plots it."""


def fit(points: npt.ArrayLike, *, n: Optional[RatioLike] = None,
        ratios: Optional[Tuple[Count, Count]] = None, teeth: Optional[str] = None, nodes: Optional[Count] = None,
        cusps: Optional[Count] = None, candidates: Count = 5, max_deviation: Real = float("inf"),
        node_at: Optional[npt.ArrayLike] = None, node_tolerance: Optional[Real] = None,
        min_margin: Real = 0.0, progress: Optional[Progress] = None) -> FitResult:
    """Ranked gear trains of ratio n (or of every ratio of ratios=(P, Q), as `--ratios P,Q`; or teeth="ZS:ZP"
    or "MIN..MAX" as `--teeth`, each candidate then echoing its "teeth") whose curve
    passes nearest the path's points (an (N, 3) array of unit vectors, N >= 4, untimed; sun axis Z),
    as `sphtroch synth fit --json`: {"candidates": [{"n", "a2", "a3", "phase", "rms",
    "max_deviation", "margin" (radians), "counts": {"nodes", "crossings", "tangencies", "cusps"},
    "census_certified"}] best first, "reason" (why there is none, else ""), "dropped"}. With nodes
    and/or cusps, every candidate has exactly those counts (confirmed by classify). With
    node_at=(x, y, z), every candidate's certified census has a node within node_tolerance
    (radians, default 1e-6; only with node_at) of that point ("node_distance": to its nearest
    node). progress: as for synth_points (the ratios done).
    Raises InvalidInput naming "points", "n", "ratios", "teeth", "nodes", "cusps", "candidates",
    "max-deviation", "node-at", "node-tolerance" or "progress"."""


def fit_text(points: npt.ArrayLike, *, n: Optional[RatioLike] = None,
             ratios: Optional[Tuple[Count, Count]] = None, teeth: Optional[str] = None, nodes: Optional[Count] = None,
             cusps: Optional[Count] = None, candidates: Count = 5, max_deviation: Real = float("inf"),
             node_at: Optional[npt.ArrayLike] = None, node_tolerance: Optional[Real] = None,
             min_margin: Real = 0.0, progress: Optional[Progress] = None) -> str:
    """What fit computes, as the text `sphtroch synth fit` prints (the same arguments, the same
    refusals): the wanted counts, the reason when there is no candidate, then each candidate best
    first with its distances, margin, census and the command that plots it."""
