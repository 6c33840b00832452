C=======================================================================
C     CMRAND - THE NEXT NUMBER OF THE MINIMAL STANDARD GENERATOR
C                                                               (SHARED)
C     SOURCE:  LEWIS, GOODMAN AND MILLER, IBM SYST. J. 8 (1969) 136:
C              X := 16807 X MOD (2**31 - 1), COMPUTED BY SCHRAGE'S
C              METHOD SO THAT NO PRODUCT EXCEEDS 2**31 - 1.
C     ISEED   (IN/OUT) INTEGER  THE LAST NUMBER, 1 .. 2**31 - 2; ON
C                               RETURN THE NEXT ONE
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMRAND(ISEED)
      IMPLICIT NONE
      INTEGER ISEED
C     ---- LOCAL -------------------------------------------------------
      INTEGER IA, IM, IQ, IR, K
      PARAMETER (IA = 16807, IM = 2147483647, IQ = 127773, IR = 2836)
C
      K = ISEED / IQ
      ISEED = IA * (ISEED - K * IQ) - IR * K
      IF (ISEED .LT. 0) ISEED = ISEED + IM
      RETURN
C     END OF CMRAND
      END
