C=======================================================================
C     CMFEQ  - ARE TWO FRAMES THE SAME, WITH NO CYCLE ON EITHER (SHARED)
C     SOURCE:  RECONSTRUCTED.
C     I, J    (INPUT)  INTEGER  FRAMES OF /CMFRT/
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      LOGICAL FUNCTION CMFEQ(I, J)
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
      CMFEQ = JFX(I) .EQ. JFX(J) .AND. JFY(I) .EQ. JFY(J) .AND.
     1        JFDX(I) .EQ. JFDX(J) .AND. JFDY(I) .EQ. JFDY(J) .AND.
     2        JFK(I) .EQ. JFK(J) .AND. JFCYC(I) .EQ. 0 .AND.
     3        JFCYC(J) .EQ. 0
      RETURN
C     END OF CMFEQ
      END
