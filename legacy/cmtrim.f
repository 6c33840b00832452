C=======================================================================
C     CMTRIM - LENGTH OF A STRING WITHOUT ITS TRAILING BLANKS   (SHARED)
C     SOURCE:  RECONSTRUCTED (FORTRAN 77 HAS NO LEN_TRIM).
C     STR     (INPUT)  CHARACTER  THE STRING
C     L       (OUTPUT) INTEGER    POSITION OF THE LAST NON-BLANK, OR 0
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMTRIM(STR, L)
      IMPLICIT NONE
      CHARACTER*(*) STR
      INTEGER L
C
      L = LEN(STR)
   10 CONTINUE
      IF (L .GT. 0) THEN
         IF (STR(L:L) .EQ. ' ') THEN
            L = L - 1
            GOTO 10
         END IF
      END IF
      RETURN
C     END OF CMTRIM
      END
