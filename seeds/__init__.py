"""The neighbouring systems: what the other four source documents describe,
re-created beside the EM-703 chain (docs/SOURCES.md names the documents).

One module per document: :mod:`seeds.seed001` (DXF drawings to a deck),
:mod:`seeds.seed002` (the Ural-1's milling programs and the 5121 tape),
:mod:`seeds.seed003` (a PC shell's binary program over a CRC-checked line),
:mod:`seeds.seed004` (tape codes, long moves split into frames,
interpolators); :mod:`seeds.contour` holds the contours of lines and arcs
that seeds 001 and 002 share.  They may use the oracle (:mod:`harness`) to
read and write decks; the oracle never uses them.
"""
