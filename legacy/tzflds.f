C=======================================================================
C     TZFLDS - THE COLUMNS A CARD TYPE READS                   (TENZOR)
C     SOURCE:  RECONSTRUCTED, DOCS/CARDS.MD (THE TABLES OF EACH CARD).
C     ONE TABLE FOR THE TWO CHECKS THAT NEED IT: THE COLUMNS A CARD
C     DOES NOT READ (TZUNRD) AND A NAME CARD THAT READS AS A DATA
C     CARD (TZLOOK). THE READERS OF THE CARDS (TZPCRD, TZDCRD, ...)
C     READ EXACTLY THESE FIELDS.
C     CH      (INPUT)  CHARACTER*1  THE CARD TYPE: P, D, L, +, O, A, M,
C                                   C, E, OR N FOR THE NAME CARD
C     NF      (OUTPUT) INTEGER      NUMBER OF NUMBER FIELDS, 0 TO 9
C     IA, IB  (OUTPUT) INTEGER(9)   FIRST AND LAST COLUMN OF EACH
C     ND      (OUTPUT) INTEGER(9)   ITS IMPLIED DECIMALS (0 = INTEGER)
C     NL      (OUTPUT) INTEGER      NUMBER OF LETTER COLUMNS, 0 TO 2
C     LC      (OUTPUT) INTEGER(2)   THE LETTER COLUMNS (DIRECTION,
C                                   TAPE, CODE, ORDER)
C     MASK    (OUTPUT) CHARACTER*72 'R' IN EACH COLUMN OF 1-72 THE
C                                   TYPE READS (THE NAME CARD: 1-18),
C                                   BLANK IN THE OTHERS
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZFLDS(CH, NF, IA, IB, ND, NL, LC, MASK)
      IMPLICIT NONE
      CHARACTER*1 CH
      INTEGER NF, IA(9), IB(9), ND(9), NL, LC(2)
      CHARACTER*72 MASK
C     ---- LOCAL -------------------------------------------------------
C     THE NUMBER FIELDS OF P (1-9), D (10-16), L (17-19), + (20-21),
C     O (22-24), A (25-30) AND M (31-36), IN CARD ORDER
      INTEGER MXF
      PARAMETER (MXF = 36)
      INTEGER JA(MXF), JB(MXF), JD(MXF), JFST(7), JLST(7), I, J, K
      CHARACTER*7 TYPES
      DATA TYPES / 'PDL+OAM' /
      DATA JFST / 1, 10, 17, 20, 22, 25, 31 /
      DATA JLST / 9, 16, 19, 21, 24, 30, 36 /
      DATA JA / 3, 11, 21, 31, 39, 47, 55, 63, 66,
     1          11, 21, 31, 39, 47, 51, 61,
     2          11, 21, 31,  11, 21,  11, 21, 31,
     3          11, 21, 31, 41, 51, 61,
     4          11, 21, 31, 41, 51, 56 /
      DATA JB / 10, 20, 30, 38, 46, 54, 62, 65, 68,
     1          20, 30, 38, 46, 50, 60, 70,
     2          20, 30, 38,  20, 30,  20, 30, 40,
     3          20, 30, 40, 50, 60, 70,
     4          20, 30, 40, 50, 55, 60 /
      DATA JD /  0,  2,  2,  2,  2,  2,  2,  0,  0,
     1           2,  2,  2,  2,  0,  2,  2,
     2           2,  2,  2,   2,  2,   2,  2,  2,
     3           2,  2,  2,  2,  2,  2,
     4           2,  2,  2,  2,  0,  0 /
C
      NF = 0
      NL = 0
      MASK = 'R'
      IF (CH .EQ. 'N') MASK(1:18) = 'RRRRRRRRRRRRRRRRRR'
      K = INDEX(TYPES, CH)
      IF (K .EQ. 0) RETURN
      DO 10 I = JFST(K), JLST(K)
         NF = NF + 1
         IA(NF) = JA(I)
         IB(NF) = JB(I)
         ND(NF) = JD(I)
         DO 5 J = JA(I), JB(I)
            MASK(J:J) = 'R'
    5    CONTINUE
   10 CONTINUE
      IF (CH .EQ. 'O' .OR. CH .EQ. 'A' .OR. CH .EQ. 'M') THEN
         NL = 1
         LC(1) = 2
      ELSE IF (CH .EQ. 'P') THEN
         NL = 2
         LC(1) = 70
         LC(2) = 71
      END IF
      DO 20 I = 1, NL
         MASK(LC(I):LC(I)) = 'R'
   20 CONTINUE
      RETURN
C     END OF TZFLDS
      END
