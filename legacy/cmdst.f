C=======================================================================
C     CMDST  - THE DISTANCE BETWEEN TWO POINTS                  (SHARED)
C     SOURCE:  RECONSTRUCTED.
C     IX1..IY2 (INPUT) INTEGER  THE POINTS, 0.01 MM
C     CHANGES: 2026-11-22 FIRST RECONSTRUCTION
C=======================================================================
      DOUBLE PRECISION FUNCTION CMDST(IX1, IY1, IX2, IY2)
      IMPLICIT NONE
      INTEGER IX1, IY1, IX2, IY2
C
      CMDST = SQRT((DBLE(IX1) - IX2)**2 + (DBLE(IY1) - IY2)**2)
      RETURN
C     END OF CMDST
      END
