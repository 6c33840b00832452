C=======================================================================
C     CMCELL - THE GRID CELL OF A POINT, CLAMPED TO THE GRID    (SHARED)
C     SOURCE:  RECONSTRUCTED.
C     IX, IY  (INPUT)  INTEGER  THE POINT, 0.01 MM
C     IC      (OUTPUT) INTEGER  THE CELL, 1..NGX*NGY
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMCELL(IX, IY, IC)
      IMPLICIT NONE
      INTEGER IX, IY, IC
C     ---- /CMITM/ THE ITEMS OF A TAPE AND THE TOUR THROUGH THEM -------
      INTEGER MXITM
      PARAMETER (MXITM = 300000)
      INTEGER NITM, IKND(MXITM), IREF(MXITM), IEX(MXITM), IEY(MXITM),
     1        IXX(MXITM), IXY(MXITM), ITOUR(MXITM), IPOS(MXITM),
     2        IORI(MXITM), NJOB
      COMMON /CMITM/ NITM, IKND, IREF, IEX, IEY, IXX, IXY, ITOUR, IPOS,
     1               IORI, NJOB
      SAVE /CMITM/
C     ---- /CMTWK/ WORK SPACE OF THE TOUR: GRID, NEIGHBOURS, QUEUE -----
      INTEGER MXPT, MXCEL, MXNB
      PARAMETER (MXPT = 2 * MXITM, MXCEL = 2 * MXITM, MXNB = 16)
      INTEGER NGX, NGY, KGX0, KGY0, KGCS, KDSX, KDSY, KDTX, KDTY,
     1        KQHD, KQN, KWORK, KWMAX,
     2        KQX(MXPT), KQY(MXPT), KCST(MXCEL + 1), KCCN(MXCEL),
     3        KCEL(MXPT), KSLT(MXPT), KNB(MXNB, MXPT), KQUE(MXITM),
     4        LQUE(MXITM)
      COMMON /CMTWK/ NGX, NGY, KGX0, KGY0, KGCS, KDSX, KDSY, KDTX, KDTY,
     1               KQHD, KQN, KWORK, KWMAX, KQX, KQY, KCST, KCCN,
     2               KCEL, KSLT, KNB, KQUE, LQUE
      SAVE /CMTWK/
C     ---- LOCAL -------------------------------------------------------
      INTEGER IGX, IGY
C
      IGX = MAX(0, MIN(NGX - 1, (IX - KGX0) / KGCS))
      IGY = MAX(0, MIN(NGY - 1, (IY - KGY0) / KGCS))
      IF (IX .LT. KGX0) IGX = 0
      IF (IY .LT. KGY0) IGY = 0
      IC = IGX + IGY * NGX + 1
      RETURN
C     END OF CMCELL
      END
