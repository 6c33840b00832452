"""Independent Python oracle for the EM-703 / TENZOR re-creation.

Modules: ``tape`` (decoder and encoder of EM-703 tape images, code table
transcribed from the 1977 report), ``report`` (the report's hand-coded
examples as text goldens), ``f77check`` (the FORTRAN 77 style checker of
SPEC section 7).  Run ``python -m harness --help`` for the command line.
"""
