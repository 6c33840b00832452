C=======================================================================
C     TZLOOK - DOES A NAME CARD READ AS A DATA CARD?           (TENZOR)
C     SOURCE:  RECONSTRUCTED, DOCS/CARDS.MD ("PACKAGES"). A DECK THAT
C              LOST ITS NAME CARD WOULD OTHERWISE NAME THE PACKAGE
C              AFTER ITS FIRST DATA CARD AND DROP THAT CARD'S PAD OR
C              PARAMETERS WITHOUT A WORD.
C     THE CARD READS AS A DATA CARD WHEN COLUMN 1 IS P, D, L, +, O, A
C     OR M, EVERY NUMBER FIELD OF THAT TYPE HOLDS A WELL-FORMED NUMBER
C     OR IS BLANK, AT LEAST ONE OF THEM IS NOT BLANK, ITS LETTER
C     COLUMNS HOLD LETTERS THE TYPE ACCEPTS, AND NO OTHER COLUMN OF
C     2-72 IS USED. A NAME THAT MUST LOOK SO IS WRITTEN WITH A
C     CHARACTER IN A COLUMN THE TYPE DOES NOT READ ('P_    9999', NOT
C     'P     9999', FMAX 9999: THE FILE NAME IS THE SAME, BLANKS BECOME
C     _ IN IT).
C     CARD    (INPUT)  CHARACTER*80  THE NAME CARD
C     LDATA   (OUTPUT) INTEGER       1 IF IT READS AS A DATA CARD
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZLOOK(CARD, LDATA)
      IMPLICIT NONE
      CHARACTER*80 CARD
      INTEGER LDATA
C     ---- LOCAL -------------------------------------------------------
      INTEGER NF, IA(9), IB(9), ND(9), NL, LC(2), I, J, NUSED, IVAL,
     1        LB, IERR, IECOL
      CHARACTER*1 CH, CL
      CHARACTER*72 MASK
C
      LDATA = 0
      CH = CARD(1:1)
      IF (INDEX('PDL+OAM', CH) .EQ. 0) RETURN
      CALL TZFLDS(CH, NF, IA, IB, ND, NL, LC, MASK)
C     ---- NOTHING IN THE COLUMNS THE TYPE DOES NOT READ ---------------
      DO 40 J = 2, 72
         IF (MASK(J:J) .EQ. ' ' .AND. CARD(J:J) .NE. ' ') RETURN
   40 CONTINUE
C     ---- ITS LETTERS -------------------------------------------------
      DO 50 I = 1, NL
         CL = CARD(LC(I):LC(I))
         IF (CH .EQ. 'O' .OR. CH .EQ. 'A') THEN
            IF (CL .NE. '+' .AND. CL .NE. '-') RETURN
         ELSE IF (CH .EQ. 'M') THEN
            IF (INDEX(' SBL', CL) .EQ. 0) RETURN
         ELSE IF (LC(I) .EQ. 70) THEN
            IF (INDEX(' 8K', CL) .EQ. 0) RETURN
         ELSE
            IF (INDEX(' OD', CL) .EQ. 0) RETURN
         END IF
   50 CONTINUE
C     ---- ITS NUMBERS -------------------------------------------------
      NUSED = 0
      DO 60 I = 1, NF
         CALL CMNUM(CARD, IA(I), IB(I), ND(I), IVAL, LB, IERR, IECOL)
         IF (IERR .NE. 0) RETURN
         IF (LB .EQ. 0) NUSED = NUSED + 1
   60 CONTINUE
      IF (NUSED .GT. 0) LDATA = 1
      RETURN
C     END OF TZLOOK
      END
