"""The benchmark's outputs: CSV, the table, the targets, and SVG plots.

The SVG is written by hand (no plotting library, so the same figures give
the same bytes): four small log-scale charts of the boards' figures against
the board size (``bench.svg``), and two of the TSPLIB instances, the tours
over the optimum and TENZOR's time over LKH-3's (``tsplib.svg``).
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Sequence
from pathlib import Path

from harness.files import write_whole

#: CSV columns, in order, with what each holds.
COLUMNS: dict[str, str] = {
    "board": "board name (distribution and pads)",
    "dist": "uniform, clustered or grid",
    "pads": "pads on the board",
    "cards": "cards of the deck",
    "items": "tour items of the two pad tapes (D cards)",
    "conductors": "L cards",
    "tenzor_s": "TENZOR deck to tapes, wall seconds, minimum of the repeats",
    "tenzor_s_max": "the slowest repeat",
    "tenzor_cpu_s": "TENZOR's CPU time (user + system), minimum of the repeats",
    "repeats": "runs timed (at least --repeats; short runs until --min-seconds, at most 30)",
    "peak_rss_mb": "TENZOR's peak resident set size, MiB (VmHWM)",
    "frames": "frames on the three tapes",
    "rows": "rows on the three tapes (tape length at 2.54 mm a row)",
    "frames_per_s": "frames / tenzor_s",
    "rows_per_s": "rows / tenzor_s",
    "drawn_m": "length drawn with the tool down, three tapes (simulated), m",
    "travel_m": "length travelled with the tool raised, three tapes (simulated), m",
    "run_min": "estimated run time of the three tapes (5.5 m/min, arcs 1.5), min",
    "cyc_small": "small-pad tape: rows as punched / rows with every cycle unrolled",
    "cyc_large": "the same, large-pad tape",
    "cyc_cond": "the same, conductor tape",
    "cyc_pads": "the same, the two pad tapes together",
    "cyc_all": "the same, all three tapes together",
    "tour_deck_m": "pad tapes: tour through the item centres in deck order, m",
    "tour_nn_m": "the same, plain nearest neighbour",
    "tour_tenzor_m": "the same, TENZOR's order read back from its tapes",
    "tour_ref_m": "the same, LKH-3 (elkai) reference",
    "tenzor_vs_ref": "tour_tenzor_m / tour_ref_m",
    "nn_vs_ref": "tour_nn_m / tour_ref_m",
    "ref_s": "LKH-3 seconds (both pad tapes)",
    "nn_s": "nearest neighbour seconds (Python)",
    "time_vs_ref": "tenzor_s / ref_s",
    "pad_travel_m": "TENZOR's raised travel on the two pad tapes (simulated: also inside rows), m",
    "verify_s": "python -m harness verify of the deck and TENZOR's tapes, wall seconds, one run "
                "(blank: not checked, see --verify-dists, --verify-min)",
    "verify_cpu_s": "the same run's CPU time (user + system)",
    "verify_rss_mb": "its peak resident set size, MiB (VmHWM)",
}

#: The targets of docs/PERFORMANCE.md: 100 000 pads in 2 s, a tour within 5 % of LKH-3's.
TARGET_SECONDS_100K = 2.0
TARGET_TOUR_RATIO = 1.05
TARGET_TIME_RATIO = 0.10
TARGET_CYCLE_RATIO = 0.60
TARGET_RSS_MB_100K = 200.0
#: The oracle's targets: ``harness verify`` of 100 000 pads in under 60 s and 2 GB.
TARGET_VERIFY_S_100K = 60.0
TARGET_VERIFY_MB_100K = 2048.0


def _fmt(value: object) -> str:
    """A CSV field: a float as the shortest text that reads back as the same
    float, so that ``--report`` prints what the run printed and gives the
    same verdicts (with six digits, a re-print once gave LKH-3's 108.54 s
    on pcb3038 as 108.55); blank for none."""
    if value is None or value == "":
        return ""
    if isinstance(value, float):
        return "" if math.isnan(value) else repr(float(value))
    return str(value)


def write_csv(rows: Sequence[dict], path: Path) -> None:
    f = io.StringIO()
    w = csv.writer(f, lineterminator="\n")
    w.writerow(COLUMNS)
    for r in rows:
        w.writerow([_fmt(r.get(c)) for c in COLUMNS])
    write_whole(path, f.getvalue())


def read_csv(path: Path) -> list[dict[str, str]]:
    with path.open(newline="", encoding="ascii") as f:
        return list(csv.DictReader(f))


#: Columns of the printed table: (heading, key, format).
TABLE: tuple[tuple[str, str, str], ...] = (
    ("board", "board", "s"), ("pads", "pads", "d"), ("items", "items", "d"),
    ("TENZOR s", "tenzor_s", ".3f"), ("CPU s", "tenzor_cpu_s", ".3f"),
    ("RSS MB", "peak_rss_mb", ".1f"),
    ("frames/s", "frames_per_s", ".3g"), ("rows/s", "rows_per_s", ".3g"),
    ("travel m", "travel_m", ".1f"), ("run min", "run_min", ".1f"),
    ("cyc S", "cyc_small", ".2f"), ("cyc L", "cyc_large", ".2f"),
    ("cyc C", "cyc_cond", ".2f"),
    ("cyc all", "cyc_all", ".2f"),
    ("deck m", "tour_deck_m", ".1f"), ("NN m", "tour_nn_m", ".2f"),
    ("TENZOR m", "tour_tenzor_m", ".2f"), ("LKH m", "tour_ref_m", ".2f"),
    ("T/LKH", "tenzor_vs_ref", ".3f"), ("NN/LKH", "nn_vs_ref", ".3f"),
    ("LKH s", "ref_s", ".3g"), ("Ts/LKHs", "time_vs_ref", ".4f"),
    ("verify s", "verify_s", ".1f"), ("verify MB", "verify_rss_mb", ".0f"),
)


def _cell(value: object, fmt: str) -> str:
    if value is None or value == "" or (isinstance(value, float) and math.isnan(value)):
        return "-"
    if fmt == "s":
        return str(value)
    if fmt == "d":
        return str(int(float(value)))
    v = float(value)
    if fmt.endswith("g") and v >= 1000:
        return f"{v:.3g}".replace("e+0", "e").replace("e+", "e")
    return format(v, fmt)


def table(rows: Sequence[dict], markdown: bool = False,
          columns: Sequence[tuple[str, str, str]] | None = None) -> str:
    columns = TABLE if columns is None else columns
    heads = [h for h, _, _ in columns]
    body = [[_cell(r.get(k), f) for _, k, f in columns] for r in rows]
    if markdown:
        out = ["| " + " | ".join(heads) + " |",
               "|" + "|".join("---" if i == 0 else "--:" for i in range(len(heads))) + "|"]
        out += ["| " + " | ".join(line) + " |" for line in body]
        return "\n".join(out) + "\n"
    widths = [max(len(h), *(len(b[i]) for b in body)) if body else len(h)
              for i, h in enumerate(heads)]
    lines = ["  ".join(h.rjust(w) if i else h.ljust(w) for i, (h, w) in enumerate(zip(heads, widths)))]
    lines.append("  ".join("-" * w for w in widths))
    for b in body:
        lines.append("  ".join(c.rjust(w) if i else c.ljust(w)
                               for i, (c, w) in enumerate(zip(b, widths))))
    return "\n".join(lines) + "\n"


def _num(r: dict, key: str) -> float | None:
    v = r.get(key)
    if v is None or v == "":
        return None
    v = float(v)
    return None if math.isnan(v) else v


def targets(rows: Sequence[dict]) -> list[tuple[str, bool | None, str]]:
    """Each target of docs/PERFORMANCE.md: (what, met (None: not measured), the figures)."""
    out: list[tuple[str, bool | None, str]] = []
    big = [r for r in rows if int(float(r["pads"])) >= 100000]
    if big:
        worst = max(big, key=lambda r: _num(r, "tenzor_s"))
        s = _num(worst, "tenzor_s")
        out.append((f"100 000 pads deck to tapes < {TARGET_SECONDS_100K:g} s",
                    all(_num(r, "tenzor_s") < TARGET_SECONDS_100K for r in big),
                    ", ".join(f"{r['board']} {_num(r, 'tenzor_s'):.2f} s" for r in big)
                    + f" (worst {s / TARGET_SECONDS_100K:.0%} of the limit)"))
    else:
        out.append((f"100 000 pads deck to tapes < {TARGET_SECONDS_100K:g} s", None,
                    "no 100 000-pad board in this run"))
    mid = [r for r in rows if 1000 <= int(float(r["pads"])) <= 10000]
    have = [r for r in mid if _num(r, "tenzor_vs_ref") is not None]
    if have:
        worst = max(have, key=lambda r: _num(r, "tenzor_vs_ref"))
        out.append((f"travel within {TARGET_TOUR_RATIO - 1:.0%} of LKH-3, 1 000-10 000 pads",
                    all(_num(r, "tenzor_vs_ref") <= TARGET_TOUR_RATIO for r in have)
                    and len(have) == len(mid),
                    ", ".join(f"{r['board']} {_num(r, 'tenzor_vs_ref'):.3f}" for r in have)
                    + f" (worst {worst['board']}: +{_num(worst, 'tenzor_vs_ref') - 1:.1%})"))
        worst = max(have, key=lambda r: _num(r, "time_vs_ref"))
        out.append((f"TENZOR's time at most {TARGET_TIME_RATIO:g} of LKH-3's, 1 000-10 000 pads",
                    all(_num(r, "time_vs_ref") <= TARGET_TIME_RATIO for r in have),
                    ", ".join(f"{r['board']} {_num(r, 'time_vs_ref'):.4f}" for r in have)
                    + f" (worst {worst['board']})"))
    else:
        out.append((f"travel within {TARGET_TOUR_RATIO - 1:.0%} of LKH-3, 1 000-10 000 pads",
                    None, "no LKH-3 reference on a board of 1 000-10 000 pads in this run"))
    grid = [r for r in rows if r["dist"] == "grid"]
    if grid:
        out.append((f"grid boards: the pad tapes with cycles <= {TARGET_CYCLE_RATIO:.0%} "
                    "of the same tapes unrolled",
                    all(_num(r, "cyc_pads") <= TARGET_CYCLE_RATIO for r in grid),
                    ", ".join(f"{r['board']} {_num(r, 'cyc_pads'):.2f} "
                              f"(S {_num(r, 'cyc_small'):.2f}, L {_num(r, 'cyc_large'):.2f})"
                              for r in grid)))
        out.append((f"grid boards: the three tapes together with cycles <= {TARGET_CYCLE_RATIO:.0%} "
                    "of the same tapes unrolled",
                    all(_num(r, "cyc_all") <= TARGET_CYCLE_RATIO for r in grid),
                    ", ".join(f"{r['board']} {_num(r, 'cyc_all'):.2f}" for r in grid)))
        out.append(("grid boards: the conductor tape with cycles <= "
                    f"{TARGET_CYCLE_RATIO:.0%} of the same tape unrolled",
                    all(_num(r, "cyc_cond") <= TARGET_CYCLE_RATIO for r in grid),
                    ", ".join(f"{r['board']} {_num(r, 'cyc_cond'):.2f}" for r in grid)))
    if big:
        worst = max(_num(r, "peak_rss_mb") for r in big)
        out.append((f"peak memory < {TARGET_RSS_MB_100K:g} MB at 100 000 pads",
                    worst < TARGET_RSS_MB_100K,
                    ", ".join(f"{r['board']} {_num(r, 'peak_rss_mb'):.1f} MB" for r in big)))
    checked = [r for r in big if _num(r, "verify_s") is not None]
    if checked:
        out.append((f"harness verify of 100 000 pads < {TARGET_VERIFY_S_100K:g} s and "
                    f"< {TARGET_VERIFY_MB_100K / 1024:g} GB",
                    all(_num(r, "verify_s") < TARGET_VERIFY_S_100K
                        and _num(r, "verify_rss_mb") < TARGET_VERIFY_MB_100K for r in checked),
                    ", ".join(f"{r['board']} {_num(r, 'verify_s'):.1f} s "
                              f"(CPU {_num(r, 'verify_cpu_s'):.1f} s), "
                              f"{_num(r, 'verify_rss_mb'):.0f} MB" for r in checked)))
    for dist in sorted({r["dist"] for r in rows}):
        pts = sorted((int(float(r["pads"])), _num(r, "peak_rss_mb"))
                     for r in rows if r["dist"] == dist)
        if len(pts) >= 3:
            steps = [(b[1] - a[1]) / (b[0] - a[0]) * 1000 for a, b in zip(pts, pts[1:])]
            out.append((f"memory growth, {dist}", None,
                        "MB per 1 000 pads between sizes: "
                        + ", ".join(f"{s:.2f}" for s in steps)
                        + f" (baseline {pts[0][1]:.1f} MB at {pts[0][0]} pads)"))
    return out


def targets_text(rows: Sequence[dict]) -> str:
    lines = []
    for what, met, figures in targets(rows):
        mark = {True: "MET   ", False: "MISSED", None: "      "}[met]
        lines.append(f"{mark} {what}: {figures}")
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------
# The TSPLIB drilling problems (bench/tsplib.py).
# ---------------------------------------------------------------------------
#: CSV columns of tsplib.csv, in order, with what each holds.
TSPLIB_COLUMNS: dict[str, str] = {
    "instance": "TSPLIB instance",
    "nodes": "its nodes (the pads of the deck)",
    "type": "its distance function (EUC_2D: nint of the Euclidean distance)",
    "optimum": "the proven optimal tour length (TSPLIB)",
    "tenzor_len": "TENZOR's tour, the order of its small-pad tape, with the instance's distance",
    "tenzor_pct": "TENZOR's tour over the optimum, per cent",
    "tenzor_s": "TENZOR deck to tapes, wall seconds, minimum of the repeats",
    "tenzor_cpu_s": "TENZOR's CPU time (user + system), minimum of the repeats",
    "peak_rss_mb": "TENZOR's peak resident set size, MiB (VmHWM)",
    "lkh_len": "LKH-3 (elkai), one run with its default parameters, seed 1",
    "lkh_pct": "LKH-3's tour over the optimum, per cent",
    "lkh_s": "LKH-3's seconds",
    "time_vs_lkh": "tenzor_s / lkh_s",
    "ortools1_pct": "OR-Tools, guided local search for 1 s, over the optimum, per cent",
    "ortools3_pct": "the same, 3 s",
}

#: The targets of the TSPLIB boards: within 1 % of the optimum, in at most a
#: hundredth of LKH-3's time and under 1.5 s.
TARGET_TSPLIB_PCT = 1.0
TARGET_TSPLIB_TIME_RATIO = 0.01
TARGET_TSPLIB_SECONDS = 1.5

TSPLIB_TABLE: tuple[tuple[str, str, str], ...] = (
    ("instance", "instance", "s"), ("nodes", "nodes", "d"), ("optimum", "optimum", "d"),
    ("TENZOR %", "tenzor_pct", ".2f"), ("TENZOR s", "tenzor_s", ".3f"),
    ("CPU s", "tenzor_cpu_s", ".3f"), ("RSS MB", "peak_rss_mb", ".1f"),
    ("LKH-3 %", "lkh_pct", ".2f"), ("LKH-3 s", "lkh_s", ".2f"),
    ("T s/LKH s", "time_vs_lkh", ".4f"),
    ("OR-Tools 1 s %", "ortools1_pct", ".1f"), ("OR-Tools 3 s %", "ortools3_pct", ".1f"),
)


def tsplib_table(rows: Sequence[dict], markdown: bool = False) -> str:
    return table(rows, markdown, TSPLIB_TABLE)


def tsplib_targets_text(rows: Sequence[dict]) -> str:
    if not rows:
        return ""
    lines = []
    for r in rows:
        pct, secs, ratio = _num(r, "tenzor_pct"), _num(r, "tenzor_s"), _num(r, "time_vs_lkh")
        marks = [f"{'MET   ' if pct <= TARGET_TSPLIB_PCT else 'MISSED'} {r['instance']} "
                 f"within {TARGET_TSPLIB_PCT:g} % of the optimum: {pct:.2f} %",
                 f"{'MET   ' if secs < TARGET_TSPLIB_SECONDS else 'MISSED'} {r['instance']} "
                 f"under {TARGET_TSPLIB_SECONDS:g} s: {secs:.3f} s"]
        if ratio is not None:
            marks.append(f"{'MET   ' if ratio <= TARGET_TSPLIB_TIME_RATIO else 'MISSED'} "
                         f"{r['instance']} at most {TARGET_TSPLIB_TIME_RATIO:g} of LKH-3's time: "
                         f"{ratio:.4f}")
        lines += marks
    return "\n".join(lines) + "\n"


def write_tsplib_csv(rows: Sequence[dict], path: Path) -> None:
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=list(TSPLIB_COLUMNS), lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({k: _fmt(r.get(k)) for k in TSPLIB_COLUMNS})
    write_whole(path, buf.getvalue())


# ---------------------------------------------------------------------------
# SVG.
# ---------------------------------------------------------------------------
COLOURS = {"uniform": "#1f77b4", "clustered": "#d62728", "grid": "#2ca02c"}


def _esc(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def _decades(values: Sequence[float]) -> tuple[float, float]:
    """The whole decades around the positive ``values``, for a log axis."""
    return (10 ** math.floor(math.log10(min(values))),
            10 ** math.ceil(math.log10(max(values))))


def _marker(cx: float, cy: float, colour: str, marker: str) -> str:
    """A point's mark: ``circle`` and ``diamond`` filled, ``square`` and
    ``ring`` open."""
    if marker == "circle":
        return f'<circle cx="{cx:.1f}" cy="{cy:.1f}" r="3" fill="{colour}"/>'
    if marker == "ring":
        return (f'<circle cx="{cx:.1f}" cy="{cy:.1f}" r="3.5" fill="white" '
                f'stroke="{colour}" stroke-width="1.5"/>')
    if marker == "diamond":
        return (f'<path d="M{cx:.1f},{cy - 4.5:.1f} L{cx + 4.5:.1f},{cy:.1f} '
                f'L{cx:.1f},{cy + 4.5:.1f} L{cx - 4.5:.1f},{cy:.1f} Z" fill="{colour}"/>')
    return (f'<rect x="{cx - 3:.1f}" y="{cy - 3:.1f}" width="6" height="6" '
            f'fill="white" stroke="{colour}"/>')


class _Chart:
    """One chart in a box of the SVG: log-x by the numbers ``xs`` (board
    sizes), or, given ``labels``, one column per label (``xs`` then being
    their places 0, 1, ...)."""

    def __init__(self, x: float, y: float, w: float, h: float, title: str,
                 xs: Sequence[float], ylo: float, yhi: float, ylog: bool, ylabel: str,
                 labels: Sequence[str] | None = None, xlabel: str = "pads"):
        self.x, self.y, self.w, self.h = x, y, w, h
        self.labels = labels
        if labels is None:
            self.xlo, self.xhi = math.log10(min(xs)) - 0.15, math.log10(max(xs)) + 0.15
        else:
            self.xlo, self.xhi = -0.5, len(labels) - 0.5
        self.ylog = ylog
        self.ylo, self.yhi = (math.log10(ylo), math.log10(yhi)) if ylog else (ylo, yhi)
        self.parts = [f'<text x="{x + w / 2:.1f}" y="{y - 8:.1f}" text-anchor="middle" '
                      f'font-size="13" font-weight="bold">{_esc(title)}</text>',
                      f'<rect x="{x}" y="{y}" width="{w}" height="{h}" fill="none" stroke="#444"/>',
                      f'<text x="{x - 42:.1f}" y="{y + h / 2:.1f}" font-size="11" '
                      f'transform="rotate(-90 {x - 42:.1f} {y + h / 2:.1f})" '
                      f'text-anchor="middle">{_esc(ylabel)}</text>']
        for k, v in enumerate(xs):
            px = self.px(v)
            self.parts.append(f'<line x1="{px:.1f}" y1="{y + h}" x2="{px:.1f}" y2="{y + h + 4}" stroke="#444"/>')
            text = f"{v:,}" if labels is None else labels[k]
            for j, line in enumerate(text.split("\n")):
                self.parts.append(f'<text x="{px:.1f}" y="{y + h + 16 + 12 * j}" font-size="10" '
                                  f'text-anchor="middle">{_esc(line)}</text>')
        self.parts.append(f'<text x="{x + w / 2:.1f}" y="{y + h + (30 if labels is None else 44)}" '
                          f'font-size="11" text-anchor="middle">{_esc(xlabel)}</text>')
        for t in self._yticks():
            py = self.py(t)
            label = f"{t:g}"
            self.parts.append(f'<line x1="{x - 4}" y1="{py:.1f}" x2="{x + w}" y2="{py:.1f}" '
                              'stroke="#ddd"/>')
            self.parts.append(f'<text x="{x - 6}" y="{py + 3:.1f}" font-size="10" '
                              f'text-anchor="end">{label}</text>')

    def _yticks(self) -> list[float]:
        if self.ylog:
            return [10.0 ** e for e in range(math.floor(self.ylo), math.ceil(self.yhi) + 1)
                    if self.ylo - 1e-9 <= e <= self.yhi + 1e-9]
        span = self.yhi - self.ylo
        step = 10 ** math.floor(math.log10(span / 4))
        for m in (1, 2, 5, 10):
            if span / (step * m) <= 6:
                step *= m
                break
        first = math.ceil(self.ylo / step) * step
        return [first + k * step for k in range(int((self.yhi - first) / step + 1e-9) + 1)]

    def px(self, v: float) -> float:
        t = math.log10(v) if self.labels is None else v
        return self.x + (t - self.xlo) / (self.xhi - self.xlo) * self.w

    def py(self, v: float) -> float:
        t = math.log10(max(v, 1e-12)) if self.ylog else v
        t = min(max(t, self.ylo), self.yhi)
        return self.y + self.h - (t - self.ylo) / (self.yhi - self.ylo) * self.h

    def series(self, pts: Sequence[tuple[float, float]], colour: str, dashed: bool = False,
               marker: str = "circle", line: bool = True) -> None:
        """Points, joined by a line if ``line``, each with its mark (:func:`_marker`)."""
        if not pts:
            return
        if line:
            path = " ".join(f"{self.px(a):.1f},{self.py(b):.1f}" for a, b in pts)
            dash = ' stroke-dasharray="4 3"' if dashed else ""
            self.parts.append(f'<polyline points="{path}" fill="none" stroke="{colour}" '
                              f'stroke-width="1.5"{dash}/>')
        for a, b in pts:
            self.parts.append(_marker(self.px(a), self.py(b), colour, marker))

    def limit(self, value: float, label: str) -> None:
        py = self.py(value)
        self.parts.append(f'<line x1="{self.x}" y1="{py:.1f}" x2="{self.x + self.w}" '
                          f'y2="{py:.1f}" stroke="#000" stroke-dasharray="6 3"/>')
        self.parts.append(f'<text x="{self.x + self.w - 4}" y="{py - 4:.1f}" font-size="10" '
                          f'text-anchor="end">{_esc(label)}</text>')


def svg(rows: Sequence[dict]) -> str:
    """Four charts: TENZOR's time, its peak memory, the travel against
    LKH-3 and the tape length against the unrolled tape, by board size."""
    rows = [r for r in rows if r.get("pads")]
    xs = sorted({int(float(r["pads"])) for r in rows}) or [100]
    dists = [d for d in COLOURS if any(r["dist"] == d for r in rows)]

    def pts(dist: str, key: str) -> list[tuple[float, float]]:
        out = []
        for r in rows:
            v = _num(r, key)
            if r["dist"] == dist and v is not None and v > 0:
                out.append((int(float(r["pads"])), v))
        return sorted(out)

    def span(keys: Sequence[str], lo: float, hi: float, log: bool) -> tuple[float, float]:
        vals = [v for d in dists for k in keys for _, v in pts(d, k)] + [lo, hi]
        if log:
            return _decades(vals)
        a, b = min(vals), max(vals)
        pad = (b - a) * 0.08 or 0.05
        return a - pad, b + pad

    W, H, cw, ch = 980, 700, 360, 220
    charts = []
    lo, hi = span(["tenzor_s"], TARGET_SECONDS_100K, TARGET_SECONDS_100K, True)
    c = _Chart(90, 60, cw, ch, "TENZOR, deck to tapes (min of repeats)", xs, lo, hi, True,
               "seconds")
    for d in dists:
        c.series(pts(d, "tenzor_s"), COLOURS[d])
    c.limit(TARGET_SECONDS_100K, "target at 100 000 pads: 2 s")
    charts.append(c)
    lo, hi = span(["peak_rss_mb"], 0, TARGET_RSS_MB_100K, False)
    c = _Chart(560, 60, cw, ch, "TENZOR, peak resident memory", xs, max(lo, 0), hi, False, "MiB")
    for d in dists:
        c.series(pts(d, "peak_rss_mb"), COLOURS[d])
    c.limit(TARGET_RSS_MB_100K, "target at 100 000 pads: 200 MB")
    charts.append(c)
    lo, hi = span(["tenzor_vs_ref", "nn_vs_ref"], 1.0, TARGET_TOUR_RATIO, False)
    c = _Chart(90, 390, cw, ch, "pad tapes' tour / LKH-3 (filled: TENZOR, open: NN)", xs,
               lo, hi, False, "ratio to LKH-3")
    for d in dists:
        c.series(pts(d, "tenzor_vs_ref"), COLOURS[d])
        c.series(pts(d, "nn_vs_ref"), COLOURS[d], dashed=True, marker="square")
    c.limit(TARGET_TOUR_RATIO, "target: 1.05")
    charts.append(c)
    lo, hi = span(["cyc_small", "cyc_large"], 0.0, 1.0, False)
    c = _Chart(560, 390, cw, ch, "tape rows / rows unrolled (filled: small, open: large)", xs,
               max(lo, 0), min(hi, 1.05), False, "ratio")
    for d in dists:
        c.series(pts(d, "cyc_small"), COLOURS[d])
        c.series(pts(d, "cyc_large"), COLOURS[d], dashed=True, marker="square")
    c.limit(TARGET_CYCLE_RATIO, "target on grid boards: 0.60")
    charts.append(c)
    legend = []
    for k, d in enumerate(dists):
        lx = 90 + k * 140
        legend.append(f'<rect x="{lx}" y="{H - 22}" width="12" height="12" fill="{COLOURS[d]}"/>')
        legend.append(f'<text x="{lx + 18}" y="{H - 12}" font-size="12">{d}</text>')
    body = "\n".join(p for c in charts for p in c.parts) + "\n" + "\n".join(legend)
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
            f'viewBox="0 0 {W} {H}" font-family="sans-serif">\n'
            f'<rect width="{W}" height="{H}" fill="white"/>\n{body}\n</svg>\n')


#: The TSPLIB figure's series: (CSV key, legend, colour, marker), drawn in
#: this order, each a little to the right of the one before in its column.
TSPLIB_SERIES: tuple[tuple[str, str, str, str], ...] = (
    ("tenzor_pct", "TENZOR", "#1f77b4", "circle"),
    ("lkh_pct", "LKH-3, one run", "#444444", "square"),
    ("ortools1_pct", "OR-Tools, 1 s", "#ff7f0e", "ring"),
    ("ortools3_pct", "OR-Tools, 3 s", "#d62728", "diamond"),
)

#: The lowest per cent the figure shows: a tour at the optimum (0 %) is drawn there.
TSPLIB_PCT_FLOOR = 0.01


def tsplib_svg(rows: Sequence[dict]) -> str:
    """Two charts of the TSPLIB run, one column per instance (by nodes):
    each tour's per cent over the proven optimum (log scale; 0.01 and less,
    the optimum itself, on the floor) against the 1 % target, and TENZOR's
    time over LKH-3's against the hundredth."""
    rows = sorted(rows, key=lambda r: (int(float(r["nodes"])), r["instance"]))
    labels = [f"{r['instance']}\n{int(float(r['nodes'])):,}" for r in rows]
    places = list(range(len(rows)))

    def pts(key: str, shift: float = 0.0) -> list[tuple[float, float]]:
        return [(k + shift, v) for k, r in enumerate(rows)
                if (v := _num(r, key)) is not None]

    W, H, cw, ch = 980, 630, 840, 200
    pcts = [max(v, TSPLIB_PCT_FLOOR) for key, *_ in TSPLIB_SERIES for _, v in pts(key)]
    lo, hi = _decades(pcts + [TSPLIB_PCT_FLOOR, 10 * TARGET_TSPLIB_PCT])
    c1 = _Chart(100, 40, cw, ch, "tour over the proven optimum (0.01 % and less: on the floor)",
                places, lo, hi, True, "per cent", labels, "TSPLIB instance, nodes")
    for j, (key, _, colour, marker) in enumerate(TSPLIB_SERIES):
        c1.series([(a, max(v, TSPLIB_PCT_FLOOR)) for a, v in pts(key, 0.1 * (j - 1.5))],
                  colour, marker=marker, line=False)
    c1.limit(TARGET_TSPLIB_PCT, f"target: {TARGET_TSPLIB_PCT:g} %")
    lo, hi = _decades([v for _, v in pts("time_vs_lkh") if v > 0]
                      + [TARGET_TSPLIB_TIME_RATIO, 10 * TARGET_TSPLIB_TIME_RATIO])
    c2 = _Chart(100, 340, cw, ch, "TENZOR's time, deck to tapes, over LKH-3's single run",
                places, lo, hi, True, "ratio", labels, "TSPLIB instance, nodes")
    c2.series(pts("time_vs_lkh"), TSPLIB_SERIES[0][2], marker="circle", line=False)
    for k, r in enumerate(rows):
        ratio, ours, theirs = (_num(r, key) for key in ("time_vs_lkh", "tenzor_s", "lkh_s"))
        if None not in (ratio, ours, theirs):
            c2.parts.append(f'<text x="{c2.px(k):.1f}" y="{c2.py(ratio) + 14:.1f}" '
                            f'font-size="9" text-anchor="middle">{ours * 1000:.1f} ms / '
                            f'{theirs:.3g} s</text>')
    c2.limit(TARGET_TSPLIB_TIME_RATIO, f"target: {TARGET_TSPLIB_TIME_RATIO:g}")
    legend = []
    for k, (_, name, colour, marker) in enumerate(TSPLIB_SERIES):
        legend.append(_marker(106 + k * 170, H - 22, colour, marker))
        legend.append(f'<text x="{116 + k * 170}" y="{H - 18}" font-size="12">'
                      f'{_esc(name)}</text>')
    body = "\n".join(c1.parts + c2.parts + legend)
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
            f'viewBox="0 0 {W} {H}" font-family="sans-serif">\n'
            f'<rect width="{W}" height="{H}" fill="white"/>\n{body}\n</svg>\n')
