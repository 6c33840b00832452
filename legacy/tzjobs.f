C=======================================================================
C     TZJOBS - THE JOB SHEET OF A PUNCHED PACKAGE             (TENZOR)
C     SOURCE:  RECONSTRUCTED, DOCS/FILES.MD: PLAIN 'KEY = VALUE' LINES
C              FOR THE OPERATOR AND FOR THE MODERN TOOLS (WHICH TAPE,
C              WHICH TOOL, WHICH CODE, WHERE TO SET THE START POINT).
C     ICOD    (INPUT)  INTEGER  THE CODE PUNCHED: 1 = "8", 2 = CONTROL
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZJOBS(ICOD)
      IMPLICIT NONE
      INTEGER ICOD
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
C     ---- /CMSTA/ WHAT THE SIMULATED MACHINE DID WITH EACH TAPE -------
      DOUBLE PRECISION DRAWN(3), TRAVL(3), RTIME(3), BBOX(4), PWIN(4)
      INTEGER NFRT(3), NROWT(3), IENDX, IENDY, IENDT
      COMMON /CMSTA/ DRAWN, TRAVL, RTIME, BBOX, PWIN, NFRT, NROWT,
     1               IENDX, IENDY, IENDT
      SAVE /CMSTA/
C     ---- LOCAL -------------------------------------------------------
C     THE LENGTHS AND THE TIME ARE WRITTEN BY CMFDP, AS THE LISTING
C     WRITES THEM (SO THE TWO AGREE TO THE LAST DIGIT, HOWEVER LARGE)
      CHARACTER*20 SD
      CHARACTER*10 KEY(3)
      DOUBLE PRECISION VAL(3)
      INTEGER J, K, LK
      CHARACTER*6 TAPE(3)
      CHARACTER*12 S1, S2
      INTEGER L, L1, L2, LT, IU
      DATA TAPE / 'small', 'large', 'cond' /
      DATA KEY / 'drawn_mm', 'travel_mm', 'minutes' /
C
      CALL CMTRIM(PKFILE, L)
      CALL DVJOB('# EM-703 job sheet, written by TENZOR (JINR P11-10356'
     1   // ', reconstruction)')
      CALL DVJOB('name = ' // PKFILE(1:L))
      CALL CMTRIM(JOBNAM, L1)
      IF (L1 .GT. 0) CALL DVJOB('job = ' // JOBNAM(1:L1))
      IF (ICOD .EQ. 1) THEN
         CALL DVJOB('code = 8')
      ELSE
         CALL DVJOB('code = K')
      END IF
      CALL CMITOA(ISCN, S1, L1)
      CALL CMITOA(ISCD, S2, L2)
      CALL DVJOB('scale = ' // S1(1:L1) // ':' // S2(1:L2))
      CALL CMFMM(IX0, S1, L1)
      CALL DVJOB('start_x_mm = ' // S1(1:L1))
      CALL CMFMM(IY0, S1, L1)
      CALL DVJOB('start_y_mm = ' // S1(1:L1))
      IF (IORD .EQ. 1) THEN
         CALL DVJOB('order = O')
      ELSE
         CALL DVJOB('order = D')
      END IF
      CALL CMFMM(IDMAX, S1, L1)
      CALL DVJOB('dmax_mm = ' // S1(1:L1))
      DO 10 IU = 1, 3
         CALL CMTRIM(TAPE(IU), LT)
         CALL DVJOB(TAPE(IU)(1:LT) // '.tape = ' // PKFILE(1:L) // '-'
     1      // TAPE(IU)(1:LT) // '.ptp')
         CALL DVJOB(TAPE(IU)(1:LT) // '.text = ' // PKFILE(1:L) // '-'
     1      // TAPE(IU)(1:LT) // '.txt')
         CALL CMFMM(IWT(IU), S1, L1)
         CALL DVJOB(TAPE(IU)(1:LT) // '.tool_mm = ' // S1(1:L1))
         CALL CMITOA(NFRT(IU), S1, L1)
         CALL DVJOB(TAPE(IU)(1:LT) // '.frames = ' // S1(1:L1))
         CALL CMITOA(NROWT(IU), S1, L1)
         CALL DVJOB(TAPE(IU)(1:LT) // '.rows = ' // S1(1:L1))
         VAL(1) = DRAWN(IU)
         VAL(2) = TRAVL(IU)
         VAL(3) = RTIME(IU)
         DO 20 J = 1, 3
            CALL CMFDP(VAL(J), SD)
C           (CMFDP WRITES AT LEAST 0.00: THE SCAN STOPS IN SD)
            K = 1
   15       IF (SD(K:K) .EQ. ' ') THEN
               K = K + 1
               GOTO 15
            END IF
            CALL CMTRIM(KEY(J), LK)
            CALL DVJOB(TAPE(IU)(1:LT) // '.' // KEY(J)(1:LK) // ' = '
     1         // SD(K:))
   20    CONTINUE
   10 CONTINUE
      RETURN
C     END OF TZJOBS
      END
