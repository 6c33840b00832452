C=======================================================================
C     TZUNRD - WARN OF DATA IN COLUMNS A CARD DOES NOT READ    (TENZOR)
C     SOURCE:  RECONSTRUCTED, DOCS/CARDS.MD ("COLUMNS NOT READ"). A
C              SECOND VERTEX PUNCHED ON AN L CARD, A WIDTH ON A + CARD
C              OR A NUMBER ONE FIELD TOO FAR TO THE LEFT WOULD OTHERWISE
C              BE DROPPED WITHOUT A WORD.
C     EACH RUN OF COLUMNS OF 2-72 THAT THE TYPE DOES NOT READ (TZFLDS)
C     AND THAT HOLDS ANYTHING BUT BLANKS GIVES ONE WARNING, NAMING THE
C     FIRST AND THE LAST NON-BLANK COLUMN OF THE RUN (TZWARN). COLUMNS
C     73-80 ARE THE SEQUENCE FIELD AND ARE NEVER READ.
C     CARD    (INPUT)  CHARACTER*80  THE CARD
C     CH      (INPUT)  CHARACTER*1   ITS TYPE, OR N FOR THE NAME CARD
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZUNRD(CARD, CH)
      IMPLICIT NONE
      CHARACTER*80 CARD
      CHARACTER*1 CH
C     ---- LOCAL -------------------------------------------------------
      INTEGER NF, IA(9), IB(9), ND(9), NL, LC(2), J, K1, K2, LR, LT
      CHARACTER*72 MASK
      CHARACTER*60 READS, WHO
      CHARACTER*12 S1, S2
      INTEGER L1, L2
      CHARACTER*1 BLANK
C     A BLANK AS A VARIABLE: SEE CMNUM
      DATA BLANK /' '/
C
      CALL TZFLDS(CH, NF, IA, IB, ND, NL, LC, MASK)
C     ---- NOTHING TO SAY UNLESS AN UNREAD COLUMN HOLDS SOMETHING ------
C     (THE WORDS BELOW, MADE FOR EVERY CARD, WERE A TWENTIETH OF THE
C     RUN OF A DECK OF 140 000 CARDS THAT NEEDS NONE OF THEM)
      DO 30 J = 2, 72
         IF (MASK(J:J) .EQ. BLANK .AND. CARD(J:J) .NE. BLANK) GOTO 35
   30 CONTINUE
      RETURN
   35 CONTINUE
C     ---- WHAT IT READS, IN WORDS: 'COLS 1, 11-38' --------------------
      READS = 'COLS'
      LR = 4
      J = 1
   40 CONTINUE
      IF (J .LE. 72) THEN
         IF (MASK(J:J) .EQ. 'R') THEN
            K1 = J
   50       CONTINUE
            IF (J .LT. 72) THEN
               IF (MASK(J+1:J+1) .EQ. 'R') THEN
                  J = J + 1
                  GOTO 50
               END IF
            END IF
            CALL CMITOA(K1, S1, L1)
            CALL CMITOA(J, S2, L2)
            IF (LR .GT. 4) THEN
               READS(LR+1:LR+1) = ','
               LR = LR + 1
            END IF
            IF (J .EQ. K1) THEN
               READS(LR+2:) = S1(1:L1)
               LR = LR + 1 + L1
            ELSE
               READS(LR+2:) = S1(1:L1) // '-' // S2(1:L2)
               LR = LR + 2 + L1 + L2
            END IF
         END IF
         J = J + 1
         GOTO 40
      END IF
C     (ONE COLUMN ONLY, AS ON THE C AND E CARDS: 'COL 1')
      IF (INDEX(READS(1:LR), ',') .EQ. 0 .AND.
     1    INDEX(READS(1:LR), '-') .EQ. 0) THEN
         WHO = READS(5:LR)
         READS(4:) = WHO
         LR = LR - 1
      END IF
      IF (CH .EQ. 'N') THEN
         WHO = 'THE NAME CARD'
      ELSE IF (INDEX('LOAME', CH) .GT. 0) THEN
         WHO = 'AN ' // CH // ' CARD'
      ELSE
         WHO = 'A ' // CH // ' CARD'
      END IF
      CALL CMTRIM(WHO, LT)
C     ---- EACH RUN OF UNREAD COLUMNS THAT HOLDS SOMETHING -------------
      J = 2
   60 CONTINUE
      IF (J .LE. 72) THEN
         IF (MASK(J:J) .EQ. ' ') THEN
            K1 = 0
            K2 = 0
   70       CONTINUE
            IF (CARD(J:J) .NE. ' ') THEN
               IF (K1 .EQ. 0) K1 = J
               K2 = J
            END IF
            IF (J .LT. 72) THEN
               IF (MASK(J+1:J+1) .EQ. ' ') THEN
                  J = J + 1
                  GOTO 70
               END IF
            END IF
            IF (K1 .GT. 0) CALL TZWARN(K1, K2, 'NOT BLANK, BUT '
     1         // WHO(1:LT) // ' DOES NOT READ THEM (IT READS '
     2         // READS(1:LR) // '); LEAVE THEM BLANK OR MOVE THE '
     3         // 'DATA TO ITS FIELD')
         END IF
         J = J + 1
         GOTO 60
      END IF
      RETURN
C     END OF TZUNRD
      END
