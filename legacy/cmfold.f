C=======================================================================
C     CMFOLD - FOLD REPEATED FRAME PAIRS INTO CYCLES            (SHARED)
C     SOURCE:  REPORT, "SOSTAV KADRA" AND EXAMPLE 5 (THE "SAW": TWO
C              FRAMES, THE FIRST WITH TS 8); DOCS/RECONSTRUCTION.MD: ANY
C              RUN OF IDENTICAL FRAME PAIRS IS WRITTEN WITH CYC.
C     FROM FRAME I1 ON, A PAIR (A, B) FOLLOWED BY THE SAME PAIR, N TIMES
C     IN ALL (N .GE. 2), BECOMES A WITH CYC N AND B. GREEDY, LEFT TO
C     RIGHT; FRAMES THAT ALREADY CARRY A CYCLE ARE KEPT AS THEY ARE.
C     THE M FRAMES OF THE CARDS ARE BEFORE I1 AND ARE NEVER FOLDED.
C     I1      (INPUT)  INTEGER  THE FIRST FRAME THAT MAY BE FOLDED
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMFOLD(I1)
      IMPLICIT NONE
      INTEGER I1
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
      INTEGER I, IO, NC
      LOGICAL CMFEQ
      EXTERNAL CMFEQ
C
      I = I1
      IO = I1 - 1
   10 CONTINUE
      IF (I .GT. NFR) GOTO 90
      IF (JFCYC(I) .NE. 0 .AND. I .LT. NFR) THEN
         CALL CMFCPY(I, IO + 1)
         CALL CMFCPY(I + 1, IO + 2)
         IO = IO + 2
         I = I + 2
         GOTO 10
      END IF
C     HOW MANY TIMES DOES THE PAIR (I, I+1) COME IN A ROW
      NC = 1
   20 CONTINUE
      IF (I + 2 * NC + 1 .LE. NFR) THEN
         IF (JFCYC(I+1) .EQ. 0 .AND. CMFEQ(I, I + 2 * NC) .AND.
     1       CMFEQ(I + 1, I + 2 * NC + 1)) THEN
            NC = NC + 1
            GOTO 20
         END IF
      END IF
      IF (NC .GE. 2) THEN
         CALL CMFCPY(I, IO + 1)
         CALL CMFCPY(I + 1, IO + 2)
         JFCYC(IO + 1) = NC
         IO = IO + 2
         I = I + 2 * NC
      ELSE
         CALL CMFCPY(I, IO + 1)
         IO = IO + 1
         I = I + 1
      END IF
      GOTO 10
   90 CONTINUE
      NFR = IO
      RETURN
C     END OF CMFOLD
      END
