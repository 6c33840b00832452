C=======================================================================
C     CMDISP - WHERE A RUN OF FRAMES TAKES THE TOOL             (SHARED)
C     SOURCE:  REPORT, "SOSTAV KADRA" (TS REPEATS TWO FRAMES).
C     I1, I2  (INPUT)  INTEGER           THE FRAMES I1..I2 OF /CMFRT/
C     DX, DY  (OUTPUT) DOUBLE PRECISION  THE SUM OF THEIR MOVES, CYCLES
C                                        COUNTED, 0.01 MM
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMDISP(I1, I2, DX, DY)
      IMPLICIT NONE
      INTEGER I1, I2
      DOUBLE PRECISION DX, DY
C     ---- /CMFRT/ THE FRAMES OF THE TAPE BEING PUNCHED ----------------
      INTEGER MXFRM
      PARAMETER (MXFRM = 1000000)
      INTEGER NFR, LFULL, JFX(MXFRM), JFY(MXFRM), JFDX(MXFRM),
     1        JFDY(MXFRM), JFCYC(MXFRM), JFK(MXFRM), JFCRD(MXFRM),
     2        JFCOL(MXFRM)
      COMMON /CMFRT/ NFR, LFULL, JFX, JFY, JFDX, JFDY, JFCYC, JFK,
     1               JFCRD, JFCOL
      SAVE /CMFRT/
C     ---- LOCAL -------------------------------------------------------
      INTEGER I
C
      DX = 0.0D0
      DY = 0.0D0
      I = I1
   10 CONTINUE
      IF (I .GT. I2) RETURN
      IF (JFCYC(I) .GE. 2 .AND. I .LT. I2) THEN
         DX = DX + DBLE(JFCYC(I)) * (DBLE(JFDX(I)) + JFDX(I+1))
         DY = DY + DBLE(JFCYC(I)) * (DBLE(JFDY(I)) + JFDY(I+1))
         I = I + 2
      ELSE
         DX = DX + JFDX(I)
         DY = DY + JFDY(I)
         I = I + 1
      END IF
      GOTO 10
C     END OF CMDISP
      END
