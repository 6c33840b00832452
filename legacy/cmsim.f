C=======================================================================
C     CMSIM  - RUN THE TAPE BEING BUILT ON THE MACHINE, SIMULATED
C                                                               (SHARED)
C     SOURCE:  REPORT, "OPISANIE KOORDINATOGRAFA" (FIELD 1200 X 1200 MM,
C              5.5 M/MIN ON LINES, 1.5 M/MIN ON ARCS) AND "SOSTAV
C              KADRA" (TS: THE FRAME AND THE NEXT ONE ARE RUN N TIMES);
C              DOCS/TAPE.MD.
C     THE TOOL STARTS RAISED AT THE START POINT (0,0). A CYCLE IS NOT
C     UNROLLED: ONE PASS IS RUN, AND SINCE EVERY PASS IS THE FIRST ONE
C     SHIFTED BY THE SAME STEP, THE FIRST AND THE LAST PASS BOUND THE
C     PATH. POSITIONS ARE WHOLE NUMBERS OF 0.01 MM HELD IN DOUBLE
C     PRECISION, EXACT UP TO 2**53.
C     IU      (INPUT)  INTEGER  THE TAPE: 1 SMALL, 2 LARGE, 3 COND
C     ICHK    (INPUT)  INTEGER  1 = ALSO CHECK THAT THE TOOL STAYS ON
C                               THE FIELD AT THE P CARD'S START POINT
C                               AND SCALE, AND REPORT IT IF NOT
C     RESULTS IN /CMSTA/: DRAWN(IU), TRAVL(IU) MM, RTIME(IU) MINUTES,
C     BBOX (XMIN, XMAX, YMIN, YMAX, 0.01 MM FROM THE START POINT), AND
C     THE END STATE IENDX, IENDY (0.01 MM), IENDT (1 = TOOL DOWN).
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMSIM(IU, ICHK)
      IMPLICIT NONE
      INTEGER IU, ICHK
C     ---- /TZPKG/ THE PACKAGE: P CARD PARAMETERS, ITS CARD IMAGES ---
      INTEGER MXCRD
      PARAMETER (MXCRD = 200000)
      INTEGER LPKG, ICFST, NPCRD, NPERR, LECHO, IPCRD, LGEOM,
     1        IX0, IY0, IWT(3), IDMAX, ISCN, ISCD, ICODE, IORD, IFMAX,
     2        NPWRN
      COMMON /TZPKG/ LPKG, ICFST, NPCRD, NPERR, LECHO, IPCRD, LGEOM,
     1               IX0, IY0, IWT, IDMAX, ISCN, ISCD, ICODE, IORD,
     2               IFMAX, NPWRN
      CHARACTER*18 PKNAME
      CHARACTER*24 PKFILE
      CHARACTER*80 CIMG(MXCRD)
      COMMON /TZPKGC/ PKNAME, PKFILE, CIMG
      SAVE /TZPKG/, /TZPKGC/
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
      DOUBLE PRECISION FLD, BIG
      PARAMETER (FLD = 120000.0D0, BIG = 999999999.0D0)
      DOUBLE PRECISION PX, PY, QX, QY, DL, TL, TM, FB(4), SX, SY, S,
     1                 RX(2), RY(2)
      INTEGER I, J, NF, NREP, ITOOL, LOUT, K
      CHARACTER*1 TNAME(3)
      CHARACTER*12 S1, S2, S3, S4, S5
      INTEGER L1, L2, L3, L4, L5
      DATA TNAME / 'S', 'B', 'L' /
C
      PX = 0.0D0
      PY = 0.0D0
      ITOOL = 0
      LOUT = 0
      DRAWN(IU) = 0.0D0
      TRAVL(IU) = 0.0D0
      RTIME(IU) = 0.0D0
      DO 5 K = 1, 4
         BBOX(K) = 0.0D0
    5 CONTINUE
      S = DBLE(ISCN) / DBLE(ISCD)
      I = 1
C     ---- NEXT FRAME, OR FRAME PAIR OF A CYCLE ------------------------
   10 CONTINUE
      IF (I .GT. NFR) GOTO 50
      NF = 1
      NREP = 1
      IF (JFCYC(I) .GE. 2 .AND. I .LT. NFR) THEN
         NF = 2
         NREP = JFCYC(I)
      END IF
      QX = PX
      QY = PY
      FB(1) = PX
      FB(2) = PX
      FB(3) = PY
      FB(4) = PY
      DL = 0.0D0
      TL = 0.0D0
      TM = 0.0D0
      DO 20 J = I, I + NF - 1
         CALL CMFRM1(J, QX, QY, ITOOL, DL, TL, TM, FB)
   20 CONTINUE
C     THE LAST PASS IS THE FIRST SHIFTED BY (NREP-1) STEPS
      SX = (QX - PX) * (NREP - 1)
      SY = (QY - PY) * (NREP - 1)
      FB(1) = MIN(FB(1), FB(1) + SX)
      FB(2) = MAX(FB(2), FB(2) + SX)
      FB(3) = MIN(FB(3), FB(3) + SY)
      FB(4) = MAX(FB(4), FB(4) + SY)
      DRAWN(IU) = DRAWN(IU) + NREP * DL / 100.0D0
      TRAVL(IU) = TRAVL(IU) + NREP * TL / 100.0D0
      RTIME(IU) = RTIME(IU) + NREP * TM
      BBOX(1) = MIN(BBOX(1), FB(1))
      BBOX(2) = MAX(BBOX(2), FB(2))
      BBOX(3) = MIN(BBOX(3), FB(3))
      BBOX(4) = MAX(BBOX(4), FB(4))
      PX = PX + NREP * (QX - PX)
      PY = PY + NREP * (QY - PY)
C     ---- THE FIELD: 0 .. 1200 MM ON THE MACHINE, IN BOTH AXES --------
      IF (ICHK .EQ. 1 .AND. LOUT .EQ. 0) THEN
         RX(1) = IX0 + FB(1) * S
         RX(2) = IX0 + FB(2) * S
         RY(1) = IY0 + FB(3) * S
         RY(2) = IY0 + FB(4) * S
         IF (RX(1) .LT. -1.0D-6 .OR. RX(2) .GT. FLD + 1.0D-6 .OR.
     1       RY(1) .LT. -1.0D-6 .OR. RY(2) .GT. FLD + 1.0D-6) THEN
            LOUT = 1
            CALL CMFMM(IX0, S1, L1)
            CALL CMFMM(IY0, S2, L2)
            CALL CMITOA(ISCN, S3, L3)
            CALL CMITOA(ISCD, S4, L4)
            CALL CMITOA(NINT(FLD) / 100, S5, L5)
            CALL CMERR('TENZOR', JFCRD(I), JFCOL(I), 'TAPE ' //
     1         TNAME(IU) // ' LEAVES THE ' // S5(1:L5) // ' X ' //
     2         S5(1:L5) // ' MM FIELD HERE '
     3         // '(START ' // S1(1:L1) // ', ' // S2(1:L2) //
     4         ' MM, SCALE ' // S3(1:L3) // ':' // S4(1:L4) //
     5         '); MOVE THE START POINT (X0, Y0 OF THE P CARD) OR TAKE'
     6         // ' A SMALLER SCALE')
         END IF
      END IF
      I = I + NF
      GOTO 10
C     ---- THE END STATE -----------------------------------------------
   50 CONTINUE
      IF (ABS(PX) .GT. BIG) PX = 0.0D0
      IF (ABS(PY) .GT. BIG) PY = 0.0D0
      IENDX = NINT(PX)
      IENDY = NINT(PY)
      IENDT = ITOOL
      RETURN
C     END OF CMSIM
      END
