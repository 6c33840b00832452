C=======================================================================
C     TZGCLR - EMPTY THE TABLES OF THE BOARD FOR A NEW PACKAGE (TENZOR)
C     SOURCE:  RECONSTRUCTED.
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZGCLR
      IMPLICIT NONE
C     ---- /TZGEO/ THE BOARD: PADS, CONDUCTORS, CIRCLES AND ARCS -------
      INTEGER MXPAD, MXCON, MXVTX, MXARC
      PARAMETER (MXPAD = 200000, MXCON = 50000, MXVTX = 200000,
     1           MXARC = 50000)
      INTEGER NPAD, KPX(MXPAD), KPY(MXPAD), KPW(MXPAD), KPH(MXPAD),
     1        KPN(MXPAD), KPSX(MXPAD), KPSY(MXPAD), KPCRD(MXPAD),
     2        NCON, KCV1(MXCON), KCV2(MXCON), KCW(MXCON), KCCRD(MXCON),
     3        NVTX, KVX(MXVTX), KVY(MXVTX), KVCRD(MXVTX),
     4        NARC, KAX(MXARC), KAY(MXARC), KADX(MXARC), KADY(MXARC),
     5        KAXS(MXARC), KAYS(MXARC), KAK(MXARC), KACRD(MXARC),
     6        LCOPEN, LGFULL
      COMMON /TZGEO/ NPAD, KPX, KPY, KPW, KPH, KPN, KPSX, KPSY, KPCRD,
     1               NCON, KCV1, KCV2, KCW, KCCRD, NVTX, KVX, KVY,
     2               KVCRD, NARC, KAX, KAY, KADX, KADY, KAXS, KAYS,
     3               KAK, KACRD, LCOPEN, LGFULL
      SAVE /TZGEO/
C
      NPAD = 0
      NCON = 0
      NVTX = 0
      NARC = 0
      LCOPEN = 0
      LGFULL = 0
      RETURN
C     END OF TZGCLR
      END
