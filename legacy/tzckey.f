C=======================================================================
C     TZCKEY - WHICH CONTROL CARD IS THIS                     (TENZOR)
C     SOURCE:  REPORT, "PAKET ZADACHI" (THE MONITOR "DUBNA" CARDS);
C              DOCS/CARDS.MD. THE REPORT'S REPRODUCTION PRINTS # FOR *
C              AND _ FOR A BLANK, IN LOWER CASE; ALL OF THAT IS
C              ACCEPTED.
C     CARD    (INPUT)  CHARACTER*80  A CARD WITH * OR # IN COLUMN 1
C     IBAD    (INPUT)  INTEGER  NOT 0 FOR A FAULTY CARD (TZCARD): ITS
C                               KEYWORD IS TAKEN WHATEVER FOLLOWS IT, SO
C                               A FAULTY *END FILE STILL ENDS THE DECK
C     IKEY    (OUTPUT) INTEGER  1 NAME, 2 TIME, 3 PASS, 4 TAPE,
C                               5 PERSO, 6 MAIN, 7 NO LOAD LIST,
C                               8 CALL, 9 EXECUTE, 10 END FILE,
C                               0 NOT A CONTROL CARD OF THE MONITOR
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZCKEY(CARD, IBAD, IKEY)
      IMPLICIT NONE
      CHARACTER*80 CARD
      INTEGER IBAD, IKEY
C     ---- LOCAL -------------------------------------------------------
      INTEGER NKEY
      PARAMETER (NKEY = 10)
      CHARACTER*10 KEYS(NKEY)
      INTEGER LKEY(NKEY), I, K, L
      LOGICAL LARG(NKEY)
      CHARACTER*80 WORK
      CHARACTER*1 CH
      CHARACTER*26 UPPER, LOWER
      DATA UPPER / 'ABCDEFGHIJKLMNOPQRSTUVWXYZ' /
      DATA LOWER / 'abcdefghijklmnopqrstuvwxyz' /
      DATA KEYS / 'NAME', 'TIME', 'PASS', 'TAPE', 'PERSO', 'MAIN',
     1            'NOLOADLIST', 'CALL', 'EXECUTE', 'ENDFILE' /
      DATA LKEY / 4, 4, 4, 4, 5, 4, 10, 4, 7, 7 /
C     WHICH KEYWORDS TAKE AN ARGUMENT AFTER THEM (*TIME:00.05): NO LOAD
C     LIST, EXECUTE AND END FILE TAKE NOTHING, SO *EXECUTEX IS UNKNOWN
      DATA LARG / .TRUE., .TRUE., .TRUE., .TRUE., .TRUE., .TRUE.,
     1            .FALSE., .TRUE., .FALSE., .FALSE. /
C
C     COLUMNS 2-72 (73-80 ARE THE SEQUENCE FIELD), IN UPPER CASE,
C     WITHOUT BLANKS AND _
      WORK = ' '
      L = 0
      DO 10 I = 2, 72
         CH = CARD(I:I)
         K = INDEX(LOWER, CH)
         IF (K .GT. 0) CH = UPPER(K:K)
         IF (CH .NE. ' ' .AND. CH .NE. '_') THEN
            L = L + 1
            WORK(L:L) = CH
         END IF
   10 CONTINUE
      IKEY = 0
      DO 20 I = 1, NKEY
         IF (WORK(1:LKEY(I)) .EQ. KEYS(I)(1:LKEY(I))) THEN
            IF (LARG(I) .OR. L .EQ. LKEY(I) .OR. IBAD .NE. 0) IKEY = I
            RETURN
         END IF
   20 CONTINUE
      RETURN
C     END OF TZCKEY
      END
