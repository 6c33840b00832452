C=======================================================================
C     CMPLOT - THE LINE-PRINTER CONTROL PLOT OF A TAPE          (SHARED)
C     SOURCE:  REPORT: "POPUTNO MOZHNO POLUCHIT' I KONTROL'NYE RISUNKI
C              SLOEV PLAT NA GRAFOPOSTROITELE CALCOMP-565 ILI ATSPU-128"
C              (CONTROL DRAWINGS OF THE LAYERS ON A PLOTTER OR THE LINE
C              PRINTER); DOCS/RECONSTRUCTION.MD.
C     WHAT THE TOOL DRAWS (ITS CENTRE, TOOL DOWN) IS MARKED '#' ON A
C     GRID OF PRINT POSITIONS, THE START POINT '+'. THE WINDOW PWIN IS
C     THE SAME FOR THE THREE TAPES OF A PACKAGE. A PRINT POSITION IS
C     TALLER THAN IT IS WIDE (10 CHARACTERS AN INCH ACROSS, 6 LINES AN
C     INCH DOWN), SO A LINE STANDS FOR 5/3 OF THE LENGTH OF A COLUMN
C     AND THE PLOT KEEPS THE BOARD'S PROPORTIONS. AT MOST 120 COLUMNS
C     AND 80 LINES.
C     IU      (INPUT)  INTEGER  THE TAPE: 1 SMALL, 2 LARGE, 3 COND
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMPLOT(IU)
      IMPLICIT NONE
      INTEGER IU
C     ---- /CMFRT/ THE FRAMES OF THE TAPE BEING PUNCHED ----------------
      INTEGER MXFRM
      PARAMETER (MXFRM = 1000000)
      INTEGER NFR, LFULL, JFX(MXFRM), JFY(MXFRM), JFDX(MXFRM),
     1        JFDY(MXFRM), JFCYC(MXFRM), JFK(MXFRM), JFCRD(MXFRM),
     2        JFCOL(MXFRM)
      COMMON /CMFRT/ NFR, LFULL, JFX, JFY, JFDX, JFDY, JFCYC, JFK,
     1               JFCRD, JFCOL
      SAVE /CMFRT/
C     ---- /CMSTA/ WHAT THE SIMULATED MACHINE DID WITH EACH TAPE -------
      DOUBLE PRECISION DRAWN(3), TRAVL(3), RTIME(3), BBOX(4), PWIN(4)
      INTEGER NFRT(3), NROWT(3), IENDX, IENDY, IENDT
      COMMON /CMSTA/ DRAWN, TRAVL, RTIME, BBOX, PWIN, NFRT, NROWT,
     1               IENDX, IENDY, IENDT
      SAVE /CMSTA/
C     ---- LOCAL -------------------------------------------------------
      CHARACTER*12 SN
      INTEGER LN
      INTEGER MXPC, MXPR, MXEXE
      DOUBLE PRECISION ASPECT, TWOPI
      PARAMETER (MXPC = 120, MXPR = 80, MXEXE = 2000000,
     1           ASPECT = 5.0D0 / 3.0D0, TWOPI = 6.283185307179586D0)
      CHARACTER*(MXPC) GRID(MXPR)
      CHARACTER*128 LINE
      CHARACTER*12 WHAT(3)
      CHARACTER*1 TNAME(3)
      INTEGER NC, NR, I, J, NF, NREP, IREP, NEXE, N, M, L, L1, L2
      DOUBLE PRECISION W, H, CW, CH, STEP, PX, PY, QX, QY, CX, CY, R,
     1                 A0, SW, T
      CHARACTER*12 S1, S2
      DATA WHAT / 'SMALL PADS', 'LARGE PADS', 'CONDUCTORS' /
      DATA TNAME / 'S', 'B', 'L' /
C
      W = MAX(PWIN(2) - PWIN(1), 1.0D0)
      H = MAX(PWIN(4) - PWIN(3), 1.0D0)
      CW = MAX(W / (MXPC - 1), H / ((MXPR - 1) * ASPECT))
      CH = CW * ASPECT
      NC = MIN(MXPC, INT(W / CW) + 1)
      NR = MIN(MXPR, INT(H / CH) + 1)
      STEP = MIN(CW, CH) / 2.0D0
      DO 5 I = 1, NR
         GRID(I) = ' '
    5 CONTINUE
C     ---- RUN THE FRAMES, CYCLES UNROLLED, MARKING WHAT IS DRAWN ------
      PX = 0.0D0
      PY = 0.0D0
      NEXE = 0
      I = 1
   10 CONTINUE
      IF (I .GT. NFR .OR. NEXE .GT. MXEXE) GOTO 50
      NF = 1
      NREP = 1
      IF (JFCYC(I) .GE. 2 .AND. I .LT. NFR) THEN
         NF = 2
         NREP = JFCYC(I)
      END IF
      DO 40 IREP = 1, NREP
         DO 30 J = I, I + NF - 1
            NEXE = NEXE + 1
            QX = PX + JFDX(J)
            QY = PY + JFDY(J)
            IF (JFK(J) .EQ. 10) THEN
               N = MIN(100000, INT(SQRT((QX-PX)**2 + (QY-PY)**2) / STEP)
     1             + 1)
               DO 20 M = 0, N
                  T = DBLE(M) / N
                  CALL CMPMRK(GRID, NC, NR, CW, CH, PX + T * (QX - PX),
     1                        PY + T * (QY - PY), '#')
   20          CONTINUE
            ELSE IF (JFK(J) .EQ. 11 .OR. JFK(J) .EQ. 13) THEN
               CX = PX - JFX(J)
               CY = PY - JFY(J)
               R = SQRT(DBLE(JFX(J))**2 + DBLE(JFY(J))**2)
               A0 = ATAN2(DBLE(JFY(J)), DBLE(JFX(J)))
               SW = ATAN2(DBLE(JFY(J)) + JFDY(J),
     1                    DBLE(JFX(J)) + JFDX(J)) - A0
               IF (JFK(J) .EQ. 13) SW = -SW
               SW = MOD(SW, TWOPI)
               IF (SW .LE. 0.0D0) SW = SW + TWOPI
               IF (JFDX(J) .EQ. 0 .AND. JFDY(J) .EQ. 0) SW = TWOPI
               IF (JFK(J) .EQ. 13) SW = -SW
               N = MIN(100000, INT(R * ABS(SW) / STEP) + 1)
               DO 25 M = 0, N
                  T = A0 + SW * M / N
                  CALL CMPMRK(GRID, NC, NR, CW, CH, CX + R * COS(T),
     1                        CY + R * SIN(T), '#')
   25          CONTINUE
            END IF
            PX = QX
            PY = QY
   30    CONTINUE
   40 CONTINUE
      I = I + NF
      GOTO 10
   50 CONTINUE
      CALL CMPMRK(GRID, NC, NR, CW, CH, 0.0D0, 0.0D0, '+')
C     ---- PRINT IT ----------------------------------------------------
      CALL CMFMM(NINT(CW), S1, L1)
      CALL CMFMM(NINT(CH), S2, L2)
      CALL DVPRNT(' ')
      CALL CMTRIM(WHAT(IU), L)
      CALL DVPRNT(' CONTROL PLOT, TAPE ' // TNAME(IU) // ' (' //
     1   WHAT(IU)(1:L) // '): # DRAWN, + START POINT; A COLUMN IS '
     2   // S1(1:L1) // ' MM, A LINE ' // S2(1:L2) // ' MM')
      IF (NEXE .GT. MXEXE) THEN
         CALL CMITOA(MXEXE, SN, LN)
         CALL DVPRNT(' (ONLY THE FIRST ' // SN(1:LN) // ' FRAMES RUN '
     1      // 'ARE PLOTTED)')
      END IF
      LINE = ' +'
      DO 60 I = 1, NC
         LINE(2+I:2+I) = '-'
   60 CONTINUE
      LINE(NC+3:NC+3) = '+'
      CALL DVPRNT(LINE)
      DO 70 I = 1, NR
         LINE = ' |' // GRID(I)(1:NC) // '|'
         CALL DVPRNT(LINE)
   70 CONTINUE
      LINE = ' +'
      DO 80 I = 1, NC
         LINE(2+I:2+I) = '-'
   80 CONTINUE
      LINE(NC+3:NC+3) = '+'
      CALL DVPRNT(LINE)
      RETURN
C     END OF CMPLOT
      END
