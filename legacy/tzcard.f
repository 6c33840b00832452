C=======================================================================
C     TZCARD - READ THE NEXT CARD AND CHECK ITS CHARACTERS    (TENZOR)
C     SOURCE:  RECONSTRUCTED, DOCS/CARDS.MD: A CARD IS AT MOST 80
C              COLUMNS OF PRINTABLE ASCII; COLUMNS 73-80 ARE THE
C              SEQUENCE FIELD.
C     A FAULTY CARD IS RETURNED WITH EACH BAD CHARACTER SHOWN AS '?',
C     SO THAT THE LISTING STAYS PRINTABLE; THE CALLER REPORTS THE FAULT
C     (IT KNOWS WHETHER THE CARD BELONGS TO A PACKAGE).
C     CARD    (OUTPUT) CHARACTER*80  THE CARD IMAGE, BLANK-FILLED
C     IEND    (OUTPUT) INTEGER       1 = NO MORE CARDS, ELSE 0
C     IBAD    (OUTPUT) INTEGER       0 = GOOD, 1 = TOO LONG, 2 = TAB,
C                                    3 = A BYTE THAT IS NOT A CARD
C                                    CHARACTER
C     IBCOL   (OUTPUT) INTEGER       COLUMN OF THE FIRST FAULT
C     MSG     (OUTPUT) CHARACTER     THE FAULT IN WORDS
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZCARD(CARD, IEND, IBAD, IBCOL, MSG)
      IMPLICIT NONE
      CHARACTER*80 CARD
      INTEGER IEND, IBAD, IBCOL
      CHARACTER*(*) MSG
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
      INTEGER NCOL, I, IC, L1
      CHARACTER*12 S1
C
      CARD = ' '
      IBAD = 0
      IBCOL = 0
      MSG = ' '
      CALL DVCARD(CARD, NCOL, IEND)
      IF (IEND .NE. 0) RETURN
      NCARD = NCARD + 1
      DO 10 I = 1, MIN(NCOL, 80)
         IC = ICHAR(CARD(I:I))
         IF (IC .LT. 32 .OR. IC .GT. 126) THEN
            IF (IBAD .EQ. 0) THEN
               IBCOL = I
               IF (IC .EQ. 9) THEN
                  IBAD = 2
                  MSG = 'TAB CHARACTER; CARDS HAVE NO TABS, USE BLANKS'
     1                  // ' TO REACH THE COLUMN'
               ELSE
                  IBAD = 3
                  CALL CMITOA(IC, S1, L1)
                  MSG = 'BYTE ' // S1(1:L1) // ' IS NOT A CARD '
     1                  // 'CHARACTER; EXPECTED PRINTABLE ASCII '
     2                  // '(32-126)'
               END IF
            END IF
            CARD(I:I) = '?'
         END IF
   10 CONTINUE
      IF (NCOL .GT. 80 .AND. IBAD .EQ. 0) THEN
         IBAD = 1
         IBCOL = 81
         CALL CMITOA(NCOL, S1, L1)
         MSG = 'LINE OF ' // S1(1:L1) // ' CHARACTERS; A CARD HAS AT '
     1         // 'MOST 80 COLUMNS (73-80 ARE THE SEQUENCE FIELD)'
      END IF
      CURC = CARD
      RETURN
C     END OF TZCARD
      END
