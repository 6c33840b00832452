C=======================================================================
C     TZMCRD - THE M CARD: ONE FRAME PROGRAMMED BY HAND        (TENZOR)
C     SOURCE:  REPORT, "SOSTAV KADRA" AND EXAMPLES 1-5 (THE FRAME OF
C              THE EM-703); DOCS/CARDS.MD. THE FRAME IS PUNCHED AS
C              GIVEN: NOT MERGED, NOT FOLDED INTO CYCLES, NOT REORDERED.
C     COLUMNS  2 THE TAPE: S SMALL PADS, B LARGE PADS, L (OR BLANK)
C              CONDUCTORS; 11-20 X, 21-30 Y, 31-40 DX, 41-50 DY
C              (F10.2 MM); 51-55 CYC (I5); 56-60 K (I5)
C     RULES    K IS 10 (TOOL DOWN, LINE), 20 (TOOL UP, LINE), 11 (ARC
C              OR CIRCLE, - DIRECTION) OR 13 (+ DIRECTION). A LINE HAS
C              NO X, Y. AN ARC HAS X AND/OR Y (THE TOOL RELATIVE TO THE
C              CENTRE), RADIUS AT MOST 10 M, AND ITS END (X+DX, Y+DY)
C              ON THE SAME CIRCLE WITHIN 0.01 MM. CYC IS BLANK, 0 OR
C              AT LEAST 2.
C     CARD    (INPUT)  CHARACTER*80  THE M CARD
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZMCRD(CARD)
      IMPLICIT NONE
      CHARACTER*80 CARD
C     ---- /TZJOB/ THE JOB: CARD COUNT, ENVELOPE, PACKAGE NAMES ------
      INTEGER MXENV, MXPKG
      PARAMETER (MXENV = 20, MXPKG = 10000)
      INTEGER NCARD, JOBERR, ICODEO, NENV, NPKG, IRCJOB, LEXEC, LENV,
     1        LSTRCT
      COMMON /TZJOB/ NCARD, JOBERR, ICODEO, NENV, NPKG, IRCJOB, LEXEC,
     1               LENV, LSTRCT
      CHARACTER*80 ENVC(MXENV)
      CHARACTER*24 PKNAMS(MXPKG)
      CHARACTER*40 JOBNAM
      CHARACTER*80 CURC
      COMMON /TZJOBC/ ENVC, PKNAMS, JOBNAM, CURC
      SAVE /TZJOB/, /TZJOBC/
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
C     ---- /CMMAN/ MANUAL FRAMES OF M CARDS, IN DECK ORDER -------------
      INTEGER MXMAN
      PARAMETER (MXMAN = 20000)
      INTEGER NMAN, MMTAP(MXMAN), MMX(MXMAN), MMY(MXMAN), MMDX(MXMAN),
     1        MMDY(MXMAN), MMCYC(MXMAN), MMK(MXMAN), MMCRD(MXMAN)
      COMMON /CMMAN/ NMAN, MMTAP, MMX, MMY, MMDX, MMDY, MMCYC, MMK,
     1               MMCRD
      SAVE /CMMAN/
C     ---- LOCAL -------------------------------------------------------
      CHARACTER*12 SN
      INTEGER LN
      INTEGER MXRAD
      PARAMETER (MXRAD = 1000000)
      INTEGER IT, IX, IY, IDX, IDY, ICYC, K, IOK, LB, LBK
      DOUBLE PRECISION RS, RE
      CHARACTER*12 S1, S2
      INTEGER L1, L2
C
      LGEOM = 1
      IOK = 1
      IT = 3
      IF (CARD(2:2) .EQ. 'S') THEN
         IT = 1
      ELSE IF (CARD(2:2) .EQ. 'B') THEN
         IT = 2
      ELSE IF (CARD(2:2) .NE. 'L' .AND. CARD(2:2) .NE. ' ') THEN
         CALL CMERR('TENZOR', NCARD, 2, 'TAPE ''' // CARD(2:2) // ''''
     1      // '; EXPECTED S (SMALL PADS), B (LARGE PADS) OR L (THE '
     2      // 'CONDUCTORS, ALSO BLANK)')
         IOK = 0
      END IF
      CALL CMFLD('TENZOR', NCARD, CARD, 11, 20, 2, 0, 'X', IX, LB, IOK)
      CALL CMFLD('TENZOR', NCARD, CARD, 21, 30, 2, 0, 'Y', IY, LB, IOK)
      CALL CMFLD('TENZOR', NCARD, CARD, 31, 40, 2, 0, 'DX', IDX, LB,
     1           IOK)
      CALL CMFLD('TENZOR', NCARD, CARD, 41, 50, 2, 0, 'DY', IDY, LB,
     1           IOK)
      CALL CMFLD('TENZOR', NCARD, CARD, 51, 55, 0, 0, 'CYC', ICYC, LB,
     1           IOK)
      CALL CMFLD('TENZOR', NCARD, CARD, 56, 60, 0, 0, 'K', K, LBK, IOK)
      IF (IOK .EQ. 0) RETURN
C     ---- THE COMMAND -------------------------------------------------
      IF (LBK .EQ. 1) THEN
         CALL CMERR('TENZOR', NCARD, 60, 'K IN COLS 56-60 IS BLANK; '
     1      // 'EVERY FRAME HAS A COMMAND: 10, 20, 11 OR 13')
         RETURN
      END IF
      IF (K .NE. 10 .AND. K .NE. 20 .AND. K .NE. 11 .AND. K .NE. 13)
     1   THEN
         CALL CMITOA(K, S1, L1)
         CALL CMERR('TENZOR', NCARD, 56, 'K ' // S1(1:L1) // ' IS NOT '
     1      // 'A COMMAND; EXPECTED 10 (DRAW), 20 (MOVE RAISED), '
     2      // '11 (ARC -) OR 13 (ARC +)')
         RETURN
      END IF
      IF (ICYC .EQ. 1 .OR. ICYC .LT. 0) THEN
         CALL CMERR('TENZOR', NCARD, 51, 'CYC MUST BE 2 OR MORE (THE '
     1      // 'FRAME PAIR IS RUN CYC TIMES), OR BLANK FOR NO CYCLE')
         RETURN
      END IF
      IF (K .EQ. 10 .OR. K .EQ. 20) THEN
C        ---- A STRAIGHT FRAME: DX, DY ONLY ----------------------------
         IF (IX .NE. 0 .OR. IY .NE. 0) THEN
            IF (IX .NE. 0) THEN
               CALL CMERR('TENZOR', NCARD, 11, 'X IS FOR ARCS (K 11, '
     1            // '13) ONLY; A STRAIGHT FRAME HAS DX, DY, X BLANK')
            ELSE
               CALL CMERR('TENZOR', NCARD, 21, 'Y IS FOR ARCS (K 11, '
     1            // '13) ONLY; A STRAIGHT FRAME HAS DX, DY, Y BLANK')
            END IF
            RETURN
         END IF
      ELSE
C        ---- AN ARC OR A CIRCLE: X, Y FROM THE CENTRE TO THE TOOL -----
         IF (IX .EQ. 0 .AND. IY .EQ. 0) THEN
            CALL CMERR('TENZOR', NCARD, 11, 'AN ARC NEEDS X OR Y, THE '
     1         // 'TOOL''S PLACE RELATIVE TO THE CENTRE; BOTH ARE ZERO')
            RETURN
         END IF
         RS = SQRT(DBLE(IX)**2 + DBLE(IY)**2)
         RE = SQRT((DBLE(IX) + IDX)**2 + (DBLE(IY) + IDY)**2)
         IF (RS .GT. MXRAD) THEN
            CALL CMERR('TENZOR', NCARD, 11, 'RADIUS OVER 10 M, THE '
     1         // 'LARGEST ARC OF THE MACHINE')
            RETURN
         END IF
         IF (ABS(RE - RS) .GT. 1.0D0) THEN
            CALL CMFMM(NINT(RS), S1, L1)
            CALL CMFMM(NINT(RE), S2, L2)
            CALL CMERR('TENZOR', NCARD, 31, 'ARC END IS OFF ITS CIRCLE:'
     1         // ' START RADIUS ' // S1(1:L1) // ' MM, END RADIUS ' //
     2         S2(1:L2) // ' MM; THEY MUST AGREE WITHIN 0.01 MM')
            RETURN
         END IF
      END IF
C     ---- THE FRAME LIMIT OF THE P CARD: AN M FRAME IS NOT SPLIT ------
C     (THE ERROR NAMES THE FIRST OF X, Y, DX, DY OVER THE LIMIT)
      IF (IFMAX .GT. 0 .AND. MAX(ABS(IX), ABS(IY), ABS(IDX), ABS(IDY))
     1    .GT. IFMAX) THEN
         LB = 41
         IF (ABS(IDX) .GT. IFMAX) LB = 31
         IF (ABS(IY) .GT. IFMAX) LB = 21
         IF (ABS(IX) .GT. IFMAX) LB = 11
         CALL CMITOA(IFMAX, S1, L1)
         CALL CMERR('TENZOR', NCARD, LB, 'THE FRAME IS LONGER THAN THE '
     1      // 'FRAME LIMIT FMAX OF THE P CARD (' // S1(1:L1) //
     2      ' PULSES); SPLIT IT INTO M CARDS OF AT MOST ' // S1(1:L1)
     3      // ' PULSES')
         RETURN
      END IF
C     ---- KEEP IT; A FULL TABLE IS REPORTED ONCE (NMAN = MXMAN + 1 THEN
C     MARKS IT; THE PACKAGE HAS AN ERROR, SO THE TABLE IS NOT USED) ----
      IF (NMAN .GE. MXMAN) THEN
         IF (NMAN .EQ. MXMAN) THEN
            CALL CMITOA(MXMAN, SN, LN)
            CALL CMERR('TENZOR', NCARD, 1, 'CAPACITY EXCEEDED: MORE '
     1         // 'THAN ' // SN(1:LN) // ' M CARDS IN ONE PACKAGE '
     2         // '(PARAMETER MXMAN)')
         END IF
         NMAN = MXMAN + 1
         RETURN
      END IF
      NMAN = NMAN + 1
      MMTAP(NMAN) = IT
      MMX(NMAN) = IX
      MMY(NMAN) = IY
      MMDX(NMAN) = IDX
      MMDY(NMAN) = IDY
      MMCYC(NMAN) = ICYC
      MMK(NMAN) = K
      MMCRD(NMAN) = NCARD
      RETURN
C     END OF TZMCRD
      END
