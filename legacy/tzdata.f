C=======================================================================
C     TZDATA - TAKE ONE DATA CARD OF A PACKAGE                (TENZOR)
C     SOURCE:  RECONSTRUCTED, DOCS/CARDS.MD (COLUMN 1 IS THE CARD TYPE).
C     CARD    (INPUT)  CHARACTER*80  THE CARD (NOT C, E OR *END FILE)
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZDATA(CARD)
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
C     ---- LOCAL -------------------------------------------------------
      CHARACTER*1 CH
      CHARACTER*26 UPPER, LOWER
      INTEGER K
      DATA UPPER / 'ABCDEFGHIJKLMNOPQRSTUVWXYZ' /
      DATA LOWER / 'abcdefghijklmnopqrstuvwxyz' /
C
C     A CARD BLANK IN COLS 1-72 IS NO CARD: COLS 73-80 ARE NEVER READ
      IF (CARD(1:72) .EQ. ' ') RETURN
      CH = CARD(1:1)
C     ANY CARD BUT + ENDS THE CONDUCTOR BEING READ
      IF (CH .NE. '+') CALL TZLCLS
      IF (CH .EQ. 'P') THEN
         CALL TZPCRD(CARD)
      ELSE IF (CH .EQ. 'M') THEN
         CALL TZMCRD(CARD)
      ELSE IF (CH .EQ. 'D') THEN
         CALL TZDCRD(CARD)
      ELSE IF (CH .EQ. 'L' .OR. CH .EQ. '+') THEN
         CALL TZLCRD(CARD)
      ELSE IF (CH .EQ. 'O' .OR. CH .EQ. 'A') THEN
         CALL TZACRD(CARD)
      ELSE IF (CH .EQ. '*' .OR. CH .EQ. '#') THEN
         CALL CMERR('TENZOR', NCARD, 1, 'CONTROL CARD INSIDE A PACKAGE;'
     1      // ' END THE PACKAGE WITH C OR E FIRST')
      ELSE IF (CH .EQ. ' ') THEN
         CALL CMERR('TENZOR', NCARD, 1, 'NO CARD TYPE IN COL 1; '
     1      // 'EXPECTED P, D, L, +, O, A, M, C OR E')
      ELSE
         K = INDEX(LOWER, CH)
         IF (K .GT. 0) THEN
            CALL CMERR('TENZOR', NCARD, 1, 'CARD TYPE ''' // CH //
     1         ''' IS LOWER CASE; CARDS ARE PUNCHED IN UPPER CASE: '''
     2         // UPPER(K:K) // '''')
         ELSE
            CALL CMERR('TENZOR', NCARD, 1, 'UNKNOWN CARD TYPE ''' // CH
     1         // '''; EXPECTED P, D, L, +, O, A, M, C OR E')
         END IF
      END IF
      RETURN
C     END OF TZDATA
      END
