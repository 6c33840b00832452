C=======================================================================
C     CMREV  - REVERSE A RUN OF FRAMES IN PLACE                 (SHARED)
C     SOURCE:  RECONSTRUCTED. THE TOUR MAY ENTER AN ITEM AT EITHER END;
C              THE ITEM IS THEN DRAWN BACKWARDS: THE FRAMES IN REVERSE
C              ORDER, EACH MOVE NEGATED, AN ARC STARTED FROM ITS END
C              (X, Y BECOME X+DX, Y+DY) IN THE OTHER DIRECTION (K 11 AND
C              K 13 SWAP). A CYCLE (A B) REPEATED N TIMES BECOMES
C              (B' A') REPEATED N TIMES, SO ITS CYC MOVES TO THE OTHER
C              FRAME.
C     I1, I2  (INPUT)  INTEGER  THE FRAMES I1..I2 OF /CMFRT/
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMREV(I1, I2)
      IMPLICIT NONE
      INTEGER I1, I2
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
      INTEGER I, J, IT
C
C     ---- THE ORDER ---------------------------------------------------
      I = I1
      J = I2
   10 CONTINUE
      IF (I .LT. J) THEN
         CALL CMSWAP(JFX(I), JFX(J))
         CALL CMSWAP(JFY(I), JFY(J))
         CALL CMSWAP(JFDX(I), JFDX(J))
         CALL CMSWAP(JFDY(I), JFDY(J))
         CALL CMSWAP(JFCYC(I), JFCYC(J))
         CALL CMSWAP(JFK(I), JFK(J))
         CALL CMSWAP(JFCRD(I), JFCRD(J))
         CALL CMSWAP(JFCOL(I), JFCOL(J))
         I = I + 1
         J = J - 1
         GOTO 10
      END IF
C     ---- EACH FRAME BACKWARDS; A CYCLE'S CYC TO ITS NEW FIRST FRAME --
      DO 20 I = I1, I2
         IF (JFCYC(I) .NE. 0 .AND. I .GT. I1) THEN
            JFCYC(I-1) = JFCYC(I)
            JFCYC(I) = 0
         END IF
         IF (JFK(I) .EQ. 11 .OR. JFK(I) .EQ. 13) THEN
            JFX(I) = JFX(I) + JFDX(I)
            JFY(I) = JFY(I) + JFDY(I)
            JFK(I) = 24 - JFK(I)
         END IF
         IT = JFDX(I)
         JFDX(I) = -IT
         IT = JFDY(I)
         JFDY(I) = -IT
   20 CONTINUE
      RETURN
C     END OF CMREV
      END
