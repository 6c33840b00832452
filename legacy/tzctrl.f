C=======================================================================
C     TZCTRL - TAKE ONE CARD OF THE JOB ENVELOPE              (TENZOR)
C     SOURCE:  REPORT, "PAKET ZADACHI"; DOCS/CARDS.MD. THE CARDS ARE
C              KEPT FOR THE HEADING OF EVERY LISTING; *NAME GIVES THE
C              JOB NAME; *MAIN MUST NAME TENZOR (ANOTHER PROGRAM WOULD
C              HAVE BEEN LOADED BY THE MONITOR INSTEAD).
C     CARD    (INPUT)  CHARACTER*80  THE CONTROL CARD
C     IKEY    (INPUT)  INTEGER  ITS KIND, FROM TZCKEY
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZCTRL(CARD, IKEY)
      IMPLICIT NONE
      CHARACTER*80 CARD
      INTEGER IKEY
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
C     ---- LOCAL -------------------------------------------------------
      CHARACTER*80 WORK, ARG
      CHARACTER*1 CH
      CHARACTER*26 UPPER, LOWER
      INTEGER I, K, IA, IB, L
      DATA UPPER / 'ABCDEFGHIJKLMNOPQRSTUVWXYZ' /
      DATA LOWER / 'abcdefghijklmnopqrstuvwxyz' /
C
      LENV = 1
      IF (NENV .LT. MXENV) THEN
         NENV = NENV + 1
         ENVC(NENV) = CARD
      ELSE
         CALL CMERR('TENZOR', NCARD, 1, 'CAPACITY EXCEEDED: MORE THAN '
     1      // '20 CONTROL CARDS IN THE JOB ENVELOPE (PARAMETER MXENV)')
      END IF
      IF (IKEY .EQ. 0) THEN
         CALL CMERR('TENZOR', NCARD, 2, 'UNKNOWN CONTROL CARD; EXPECTED'
     1      // ' NAME, TIME, PASS, TAPE, PERSO, MAIN, NO LOAD LIST, '
     2      // 'CALL, EXECUTE OR END FILE')
         RETURN
      END IF
      IF (IKEY .EQ. 9) LEXEC = 1
      IF (IKEY .NE. 1 .AND. IKEY .NE. 6) RETURN
C     ---- THE ARGUMENT: AFTER THE KEYWORD, A BLANK OR :, UPPER CASE ---
      WORK = CARD(2:80)
      DO 10 I = 1, 79
         CH = WORK(I:I)
         K = INDEX(LOWER, CH)
         IF (K .GT. 0) WORK(I:I) = UPPER(K:K)
         IF (CH .EQ. '_') WORK(I:I) = ' '
   10 CONTINUE
      IA = INDEX(WORK, 'NAME')
      IF (IKEY .EQ. 6) IA = INDEX(WORK, 'MAIN')
      IA = IA + 4
   20 CONTINUE
      IF (IA .LE. 79) THEN
         IF (WORK(IA:IA) .EQ. ' ' .OR. WORK(IA:IA) .EQ. ':') THEN
            IA = IA + 1
            GOTO 20
         END IF
      END IF
      ARG = ' '
      IF (IA .LE. 71) ARG = WORK(IA:71)
      CALL CMTRIM(ARG, L)
      IF (IKEY .EQ. 1) THEN
         JOBNAM = ARG(1:40)
         RETURN
      END IF
C     *MAIN: THE PROGRAM TO LOAD
      IB = IA + 1
      IF (ARG .NE. 'TENZOR') THEN
         IF (L .EQ. 0) THEN
            CALL CMERR('TENZOR', NCARD, MIN(IB, 80), '*MAIN NAMES NO '
     1         // 'PROGRAM; THIS SUBSYSTEM RUNS *MAIN TENZOR')
         ELSE
            CALL CMERR('TENZOR', NCARD, MIN(IB, 80), '*MAIN NAMES '
     1         // ARG(1:MIN(L, 20)) // '; THIS SUBSYSTEM RUNS '
     2         // '*MAIN TENZOR')
         END IF
      END IF
      RETURN
C     END OF TZCTRL
      END
