C=======================================================================
C     TZPCRD - THE P CARD: PARAMETERS OF THE BOARD            (TENZOR)
C     SOURCE:  RECONSTRUCTED (THE REPORT'S CARD FORM, ITS FIG. 1, IS
C              LOST), DOCS/CARDS.MD. SCALES FROM THE REPORT, "OPISANIE
C              KOORDINATOGRAFA": 1:100 1:10 1:5 1:2 1:1 2:1 5:1 50:1
C              100:1. BLANK FIELDS TAKE THE DEFAULTS SET BY TZPBEG.
C     COLUMNS  11-20 X0, 21-30 Y0 (F10.2) THE START POINT ON THE FIELD
C              31-38 W1, 39-46 W2, 47-54 W3 (F8.2) TOOLS OF THE SMALL-
C              PAD, LARGE-PAD AND CONDUCTOR TAPES; 55-62 DMAX (F8.2)
C              63-65 / 66-68 SCALE N / D (I3); 70 CODE 8 OR K;
C              71 ORDER O (OPTIMISED) OR D (DECK ORDER); 3-10 FMAX (I8)
C              THE LONGEST STRAIGHT MOVE OF ONE FRAME IN PULSES OF 0.01
C              MM, BLANK = NO LIMIT: LONGER MOVES ARE SPLIT (SEED 004,
C              A COUNTER OF N PULSES MOVES AT MOST N-1 IN A FRAME)
C     CARD    (INPUT)  CHARACTER*80  THE P CARD
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZPCRD(CARD)
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
C     ---- LOCAL -------------------------------------------------------
C     MXFLD  THE FIELD, 1200 MM; MXTOOL THE WIDEST TOOL, 20 MM
      INTEGER MXFLD, MXTOOL
      PARAMETER (MXFLD = 120000, MXTOOL = 2000)
      INTEGER NSC, ISCL(2,9), I, IOK, LB, IDF, IV(8), IC1(8), IC2(8),
     1        L1
      CHARACTER*8 NAMES(8)
      CHARACTER*12 S1
      INTEGER LSC
      DATA ISCL / 1,100, 1,10, 1,5, 1,2, 1,1, 2,1, 5,1, 50,1, 100,1 /
      DATA NSC / 9 /
      DATA NAMES / 'X0', 'Y0', 'TOOL W1', 'TOOL W2', 'TOOL W3', 'DMAX',
     1             'SCALE N', 'SCALE D' /
      DATA IC1 / 11, 21, 31, 39, 47, 55, 63, 66 /
      DATA IC2 / 20, 30, 38, 46, 54, 62, 65, 68 /
C
      IF (IPCRD .NE. 0) THEN
         CALL CMITOA(IPCRD, S1, L1)
         CALL CMERR('TENZOR', NCARD, 1, 'SECOND P CARD; CARD ' //
     1      S1(1:L1) // ' IS THE P CARD OF THIS PACKAGE, ONE IS '
     2      // 'ALLOWED')
         RETURN
      END IF
      IF (LGEOM .NE. 0) THEN
         CALL CMERR('TENZOR', NCARD, 1, 'P CARD AFTER THE GEOMETRY; IT '
     1      // 'MUST COME BEFORE THE FIRST D, L, +, O, A OR M CARD')
         RETURN
      END IF
      IPCRD = NCARD
C     ---- THE NUMBERS: BLANK KEEPS THE DEFAULT ------------------------
      IV(1) = IX0
      IV(2) = IY0
      IV(3) = IWT(1)
      IV(4) = IWT(2)
      IV(5) = IWT(3)
      IV(6) = IDMAX
      IV(7) = ISCN
      IV(8) = ISCD
      DO 10 I = 1, 8
         IOK = 1
         IDF = IV(I)
         IF (I .LE. 6) THEN
            CALL CMFLD('TENZOR', NCARD, CARD, IC1(I), IC2(I), 2, IDF,
     1                 NAMES(I), IV(I), LB, IOK)
         ELSE
            CALL CMFLD('TENZOR', NCARD, CARD, IC1(I), IC2(I), 0, IDF,
     1                 NAMES(I), IV(I), LB, IOK)
         END IF
         IF (IOK .EQ. 0) GOTO 10
C        ---- RANGES ---------------------------------------------------
         IF (I .LE. 2 .AND. (IV(I) .LT. 0 .OR. IV(I) .GT. MXFLD)) THEN
            CALL CMERR('TENZOR', NCARD, IC1(I), NAMES(I)(1:2) //
     1         ' IS OFF THE 1200 X 1200 MM FIELD; EXPECTED 0 TO '
     2         // '1200.00')
         ELSE IF (I .GE. 3 .AND. I .LE. 5 .AND.
     1            (IV(I) .LE. 0 .OR. IV(I) .GT. MXTOOL)) THEN
            CALL CMERR('TENZOR', NCARD, IC1(I), NAMES(I)(1:7) //
     1         ' OUT OF RANGE; A TOOL IS 0.01 TO 20.00 MM WIDE')
         ELSE IF (I .EQ. 6 .AND. (IV(I) .LE. 0 .OR. IV(I) .GT. MXFLD))
     1      THEN
            CALL CMERR('TENZOR', NCARD, IC1(I), 'DMAX OUT OF RANGE; THE'
     1         // ' SMALL-PAD LIMIT IS 0.01 TO 1200.00 MM')
         END IF
   10 CONTINUE
      IX0 = IV(1)
      IY0 = IV(2)
      IWT(1) = IV(3)
      IWT(2) = IV(4)
      IWT(3) = IV(5)
      IDMAX = IV(6)
      ISCN = IV(7)
      ISCD = IV(8)
C     ---- THE SCALE MUST BE ONE OF THE MACHINE'S ----------------------
      LSC = 0
      DO 20 I = 1, NSC
         IF (ISCN .EQ. ISCL(1,I) .AND. ISCD .EQ. ISCL(2,I)) LSC = I
   20 CONTINUE
      IF (LSC .EQ. 0) THEN
         CALL CMERR('TENZOR', NCARD, 63, 'SCALE IS NOT ONE OF THE '
     1      // 'MACHINE''S: 1:100 1:10 1:5 1:2 1:1 2:1 5:1 50:1 100:1')
         ISCN = 1
         ISCD = 1
      END IF
C     ---- THE FRAME LIMIT ---------------------------------------------
      IOK = 1
      CALL CMFLD('TENZOR', NCARD, CARD, 3, 10, 0, 0, 'FMAX', IFMAX, LB,
     1           IOK)
      IF (IOK .EQ. 1 .AND. IFMAX .LT. 0) THEN
         CALL CMERR('TENZOR', NCARD, 3, 'FMAX IN COLS 3-10 IS NEGATIVE;'
     1      // ' BLANK FOR NO LIMIT, ELSE THE LONGEST MOVE OF A FRAME')
         IFMAX = 0
      END IF
C     ---- CODE AND ORDER ----------------------------------------------
      IF (CARD(70:70) .EQ. ' ' .OR. CARD(70:70) .EQ. '8') THEN
         ICODE = 1
      ELSE IF (CARD(70:70) .EQ. 'K') THEN
         ICODE = 2
      ELSE
         CALL CMERR('TENZOR', NCARD, 70, 'TAPE CODE ''' // CARD(70:70)
     1      // '''; EXPECTED 8 (THE "8" CODE) OR K (WITH CONTROL)')
      END IF
      IF (CARD(71:71) .EQ. ' ' .OR. CARD(71:71) .EQ. 'O') THEN
         IORD = 1
      ELSE IF (CARD(71:71) .EQ. 'D') THEN
         IORD = 2
      ELSE
         CALL CMERR('TENZOR', NCARD, 71, 'ORDER ''' // CARD(71:71)
     1      // '''; EXPECTED O (OPTIMISED TOUR) OR D (DECK ORDER)')
      END IF
      RETURN
C     END OF TZPCRD
      END
