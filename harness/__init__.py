"""The independent Python oracle of the EM-703 re-creation.

It shares no code with the Fortran and proves it right from the outside:
``tape`` (decoder and encoder of EM-703 tape images, the code table
transcribed from the report), ``sim`` (the coordinatograph), ``shapes`` (the
ideal shapes of a board), ``deck`` (a deck read strictly into its ideal
layers), ``raster`` (coverage of a layer within a tolerance), ``verify``
(anyone's tapes against a deck), ``report`` (the report's hand-coded
examples), ``cards`` (a deck writer), ``f77check`` (the FORTRAN 77 checker
of legacy/; its rules are in legacy/README.md).  Run ``python -m harness
--help`` for the command line.
"""
