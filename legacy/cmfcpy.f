C=======================================================================
C     CMFCPY - COPY FRAME I OVER FRAME J                        (SHARED)
C     SOURCE:  RECONSTRUCTED.
C     I, J    (INPUT)  INTEGER  FRAMES OF /CMFRT/, J .LE. I
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMFCPY(I, J)
      IMPLICIT NONE
      INTEGER I, J
C     ---- /CMFRT/ THE FRAMES OF THE TAPE BEING PUNCHED ----------------
      INTEGER MXFRM
      PARAMETER (MXFRM = 1000000)
      INTEGER NFR, LFULL, JFX(MXFRM), JFY(MXFRM), JFDX(MXFRM),
     1        JFDY(MXFRM), JFCYC(MXFRM), JFK(MXFRM), JFCRD(MXFRM),
     2        JFCOL(MXFRM)
      COMMON /CMFRT/ NFR, LFULL, JFX, JFY, JFDX, JFDY, JFCYC, JFK,
     1               JFCRD, JFCOL
      SAVE /CMFRT/
C
      IF (I .EQ. J) RETURN
      JFX(J) = JFX(I)
      JFY(J) = JFY(I)
      JFDX(J) = JFDX(I)
      JFDY(J) = JFDY(I)
      JFCYC(J) = JFCYC(I)
      JFK(J) = JFK(I)
      JFCRD(J) = JFCRD(I)
      JFCOL(J) = JFCOL(I)
      RETURN
C     END OF CMFCPY
      END
