C=======================================================================
C     CMFRM1 - RUN ONE FRAME ON THE SIMULATED MACHINE          (SHARED)
C     SOURCE:  REPORT, "SOSTAV KADRA" AND EXAMPLES 1-3: X, Y ARE THE
C              TOOL'S PLACE RELATIVE TO THE CENTRE; K 13 IS THE +
C              DIRECTION (CLOCKWISE), K 11 THE - DIRECTION; A FRAME
C              WITHOUT DX, DY IS A FULL CIRCLE. K 10 LOWERS THE TOOL
C              AND DRAWS, K 20 RAISES IT AND MOVES; ARCS DRAW.
C     J       (INPUT)  INTEGER           THE FRAME IN /CMFRT/
C     QX,QY   (IN/OUT) DOUBLE PRECISION  THE TOOL, 0.01 MM
C     ITOOL   (IN/OUT) INTEGER           1 = DOWN, 0 = RAISED
C     DL, TL  (IN/OUT) DOUBLE PRECISION  DRAWN, TRAVEL LENGTH, 0.01 MM
C     TM      (IN/OUT) DOUBLE PRECISION  RUN TIME, MINUTES
C     FB      (IN/OUT) DOUBLE PRECISION  BOX XMIN, XMAX, YMIN, YMAX
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMFRM1(J, QX, QY, ITOOL, DL, TL, TM, FB)
      IMPLICIT NONE
      INTEGER J, ITOOL
      DOUBLE PRECISION QX, QY, DL, TL, TM, FB(4)
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
C     VLINE, VARC  SPEEDS, 0.01 MM A MINUTE (5.5 AND 1.5 M/MIN)
      DOUBLE PRECISION VLINE, VARC, TWOPI
      PARAMETER (VLINE = 550000.0D0, VARC = 150000.0D0,
     1           TWOPI = 6.283185307179586D0)
      DOUBLE PRECISION D, CX, CY, R, A0, A1, SW, TH, OFF, EX, EY
      INTEGER K, M
C
      K = JFK(J)
      IF (K .EQ. 10 .OR. K .EQ. 20) THEN
         D = SQRT(DBLE(JFDX(J))**2 + DBLE(JFDY(J))**2)
         IF (K .EQ. 10) THEN
            ITOOL = 1
            DL = DL + D
         ELSE
            ITOOL = 0
            TL = TL + D
         END IF
         TM = TM + D / VLINE
      ELSE
C        ---- ARC OR CIRCLE: CENTRE = TOOL - (X,Y) ---------------------
         ITOOL = 1
         CX = QX - JFX(J)
         CY = QY - JFY(J)
         R = SQRT(DBLE(JFX(J))**2 + DBLE(JFY(J))**2)
         EX = DBLE(JFX(J)) + JFDX(J)
         EY = DBLE(JFY(J)) + JFDY(J)
         A0 = ATAN2(DBLE(JFY(J)), DBLE(JFX(J)))
         A1 = ATAN2(EY, EX)
         IF (K .EQ. 13) THEN
            SW = A0 - A1
         ELSE
            SW = A1 - A0
         END IF
         SW = MOD(SW, TWOPI)
         IF (SW .LT. 0.0D0) SW = SW + TWOPI
         IF (JFDX(J) .EQ. 0 .AND. JFDY(J) .EQ. 0) SW = TWOPI
         IF (SW .LE. 0.0D0) SW = TWOPI
         DL = DL + R * SW
         TM = TM + R * SW / VARC
C        THE AXIS POINTS OF THE CIRCLE THAT THE SWEEP PASSES
         DO 10 M = 0, 3
            TH = M * TWOPI / 4.0D0
            IF (K .EQ. 13) THEN
               OFF = MOD(A0 - TH, TWOPI)
            ELSE
               OFF = MOD(TH - A0, TWOPI)
            END IF
            IF (OFF .LT. 0.0D0) OFF = OFF + TWOPI
            IF (OFF .LE. SW) THEN
               FB(1) = MIN(FB(1), CX + R * COS(TH))
               FB(2) = MAX(FB(2), CX + R * COS(TH))
               FB(3) = MIN(FB(3), CY + R * SIN(TH))
               FB(4) = MAX(FB(4), CY + R * SIN(TH))
            END IF
   10    CONTINUE
      END IF
      QX = QX + JFDX(J)
      QY = QY + JFDY(J)
      FB(1) = MIN(FB(1), QX)
      FB(2) = MAX(FB(2), QX)
      FB(3) = MIN(FB(3), QY)
      FB(4) = MAX(FB(4), QY)
      RETURN
C     END OF CMFRM1
      END
