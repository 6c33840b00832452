"""Benchmarks of TENZOR: ``python -m bench [--quick] [--out DIR]``.

For each board of :mod:`bench.boards` (uniform, clustered, grid; 100,
1 000, 10 000 and 100 000 pads, fixed seeds) the benchmark

1. writes the deck and runs the release build of TENZOR on it, timing it
   deck to tapes (the minimum of a few runs) and measuring its peak memory
   (:mod:`bench.measure`);
2. decodes the three tapes with :mod:`harness.tape` and runs them on
   :mod:`harness.sim`: frames, rows, drawn and raised length, run time, and
   the rows of the same frames with every cycle unrolled;
3. compares tours on the same pads (:mod:`bench.tours`): deck order,
   plain nearest neighbour, TENZOR's order read back from its tapes, and
   LKH-3 (elkai) as the reference;
4. on the boards chosen (``--verify-dists``, ``--verify-min``: the uniform
   boards of 10 000 pads and more by default), times ``python -m harness
   verify`` of the deck and TENZOR's tapes and measures its peak memory;
5. writes ``bench.csv``, ``bench.svg`` and ``bench.txt`` (the table and the
   targets) into the output directory and prints the table.

Timings are wall-clock on a shared 2-core machine: each is the minimum of
the repeats, which is the least disturbed by the other processes.
"""

from __future__ import annotations

import time
from pathlib import Path

from harness.files import write_whole

from . import boards, measure, tours

__all__ = ["run_board"]


def _log(message: str) -> None:
    print(message, flush=True)


def tape_tours(board: boards.Board, stats: dict[str, measure.TapeStats],
               lkh_max: int, nn_max: int) -> dict[str, float | None]:
    """The tours of the two pad tapes, summed over them (see tours.py)."""
    total = {"deck": 0.0, "nn": 0.0, "tenzor": 0.0, "ref": 0.0, "ref_s": 0.0, "nn_s": 0.0}
    ref_ok = board.size <= lkh_max and tours.lkh_available()
    nn_ok = board.size <= nn_max
    items_total = 0
    for key in ("small", "large"):
        pads = [p for p in board.pads if p.tape == key]
        items, order = tours.recover_order(stats[key].run, pads)
        tours.check_order(len(items), order)
        items_total += len(items)
        total["tenzor"] += tours.tour_length(items, order)
        total["deck"] += tours.tour_length(items, [(i, False) for i in range(len(items))])
        if nn_ok:
            t = time.perf_counter()
            nn = tours.nearest_neighbour(items)
            total["nn_s"] += time.perf_counter() - t
            tours.check_order(len(items), nn)
            total["nn"] += tours.tour_length(items, nn)
        if ref_ok and all(it.point for it in items):
            ref, seconds = tours.lkh_tour(items)
            tours.check_order(len(items), ref)
            total["ref"] += tours.tour_length(items, ref)
            total["ref_s"] += seconds
        else:
            ref_ok = False
    out: dict[str, float | None] = {"items": items_total}
    for k in ("deck", "nn", "tenzor", "ref"):
        out[k] = total[k] / 100_000            # units -> m
    out["ref_s"], out["nn_s"] = total["ref_s"], total["nn_s"]
    if not nn_ok:
        out["nn"] = out["nn_s"] = None
    if not ref_ok:
        out["ref"] = out["ref_s"] = None
    return out


def run_board(board: boards.Board, exe: Path, scratch: Path, repeats: int,
              lkh_max: int, nn_max: int, min_seconds: float = 1.0,
              verify: bool = False) -> dict:
    """Every figure of one board, as a row of the CSV (report.COLUMNS);
    with ``verify``, also the time and memory of ``python -m harness
    verify`` on its deck and TENZOR's tapes (which must pass)."""
    deck = scratch / f"{board.name}.crd"
    text = board.deck()
    write_whole(deck, text)
    out = scratch / board.name
    seconds, cpu = measure.time_tenzor(exe, deck, out, repeats, budget=min_seconds)
    rss_kb = measure.peak_rss(exe, deck, out)
    stats = measure.read_tapes(out, board.name)
    job = measure.read_job(out / f"{board.name}.job")
    for key, st in stats.items():          # the job sheet and the oracle agree
        if int(job[f"{key}.rows"]) != st.rows or int(job[f"{key}.frames"]) != st.frames:
            raise RuntimeError(f"{board.name}: job sheet and tape disagree on {key}")
    tour = tape_tours(board, stats, lkh_max, nn_max)
    checked = measure.time_verify(deck, out) if verify else None
    if checked is not None and not checked.passed:
        raise RuntimeError(f"{board.name}: harness verify finds TENZOR's tapes at fault")
    best = min(seconds)
    frames = sum(s.frames for s in stats.values())
    rows = sum(s.rows for s in stats.values())
    ref, nn = tour["ref"], tour["nn"]
    return {
        "board": board.name, "dist": board.dist, "pads": board.pad_count,
        "cards": text.count("\n"), "items": tour["items"],
        "conductors": len(board.conductors),
        "tenzor_s": best, "tenzor_s_max": max(seconds), "tenzor_cpu_s": min(cpu),
        "repeats": len(seconds),
        "peak_rss_mb": rss_kb / 1024,
        "frames": frames, "rows": rows,
        "frames_per_s": frames / best, "rows_per_s": rows / best,
        "drawn_m": sum(s.drawn_mm for s in stats.values()) / 1000,
        "travel_m": sum(s.travel_mm for s in stats.values()) / 1000,
        "run_min": sum(s.minutes for s in stats.values()),
        "cyc_small": stats["small"].cycle_ratio, "cyc_large": stats["large"].cycle_ratio,
        "cyc_cond": stats["cond"].cycle_ratio,
        "cyc_pads": ((stats["small"].rows + stats["large"].rows)
                     / (stats["small"].unrolled_rows + stats["large"].unrolled_rows)),
        "cyc_all": rows / sum(s.unrolled_rows for s in stats.values()),
        "tour_deck_m": tour["deck"], "tour_nn_m": nn, "tour_tenzor_m": tour["tenzor"],
        "tour_ref_m": ref,
        "tenzor_vs_ref": tour["tenzor"] / ref if ref else None,
        "nn_vs_ref": nn / ref if ref and nn else None,
        "ref_s": tour["ref_s"], "nn_s": tour["nn_s"],
        "time_vs_ref": best / tour["ref_s"] if tour["ref_s"] else None,
        "pad_travel_m": (stats["small"].travel_mm + stats["large"].travel_mm) / 1000,
        "verify_s": checked.seconds if checked else None,
        "verify_cpu_s": checked.cpu if checked else None,
        "verify_rss_mb": checked.peak_rss_kb / 1024 if checked else None,
    }
