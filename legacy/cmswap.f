C=======================================================================
C     CMSWAP - EXCHANGE TWO INTEGERS                            (SHARED)
C     SOURCE:  RECONSTRUCTED.
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMSWAP(IA, IB)
      IMPLICIT NONE
      INTEGER IA, IB
C     ---- LOCAL -------------------------------------------------------
      INTEGER IT
C
      IT = IA
      IA = IB
      IB = IT
      RETURN
C     END OF CMSWAP
      END
