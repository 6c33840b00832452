C=======================================================================
C     CMFLD  - READ A NUMERIC FIELD, REPORT IT IF MALFORMED     (SHARED)
C     SOURCE:  RECONSTRUCTED, DOCS/CARDS.MD. CALLS CMNUM AND TURNS ITS
C              ERROR CODE INTO A MESSAGE THAT NAMES THE FIELD, ITS
C              COLUMNS, ITS FORMAT AND WHAT WOULD BE RIGHT.
C     PROG    (INPUT)  CHARACTER  PROGRAM NAME FOR THE MESSAGE
C     ICRD    (INPUT)  INTEGER    CARD NUMBER
C     CARD    (INPUT)  CHARACTER  THE CARD IMAGE
C     IC1,IC2 (INPUT)  INTEGER    COLUMNS OF THE FIELD
C     NDEC    (INPUT)  INTEGER    IMPLIED DECIMALS (0 = INTEGER FIELD)
C     IDEF    (INPUT)  INTEGER    VALUE OF A BLANK FIELD
C     WHAT    (INPUT)  CHARACTER  NAME OF THE FIELD, E.G. 'X', 'CYC'
C     IVAL    (OUTPUT) INTEGER    THE VALUE (IDEF IF BLANK OR BAD)
C     LBLANK  (OUTPUT) INTEGER    1 IF THE FIELD WAS BLANK
C     IOK     (IN/OUT) INTEGER    SET TO 0 IF THE FIELD IS MALFORMED,
C                                 LEFT AS IT WAS OTHERWISE
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMFLD(PROG, ICRD, CARD, IC1, IC2, NDEC, IDEF, WHAT,
     1                 IVAL, LBLANK, IOK)
      IMPLICIT NONE
      CHARACTER*(*) PROG, CARD, WHAT
      INTEGER ICRD, IC1, IC2, NDEC, IDEF, IVAL, LBLANK, IOK
C     ---- LOCAL -------------------------------------------------------
      INTEGER IERR, IECOL, L1, L2, L3, LF, LW
      CHARACTER*12 S1, S2, S3
      CHARACTER*40 FMT, WHERE
      CHARACTER*100 MSG
C
      CALL CMNUM(CARD, IC1, IC2, NDEC, IVAL, LBLANK, IERR, IECOL)
      IF (LBLANK .EQ. 1) IVAL = IDEF
      IF (IERR .EQ. 0) RETURN
      IVAL = IDEF
      IOK = 0
C     ---- THE FIELD'S NAME, COLUMNS AND FORMAT ------------------------
      CALL CMITOA(IC1, S1, L1)
      CALL CMITOA(IC2, S2, L2)
      CALL CMITOA(IC2 - IC1 + 1, S3, L3)
C     THE NAME WITHOUT ITS TRAILING BLANKS (A TABLE'S NAMES ARE PADDED)
      LW = LEN(WHAT)
    5 IF (LW .GT. 1 .AND. WHAT(LW:LW) .EQ. ' ') THEN
         LW = LW - 1
         GOTO 5
      END IF
      WHERE = WHAT(1:LW) // ' IN COLS ' // S1(1:L1) // '-' // S2(1:L2)
      IF (NDEC .GT. 0) THEN
         FMT = 'F' // S3(1:L3) // '.2 SUCH AS 12.50 OR 1250'
      ELSE
         FMT = 'I' // S3(1:L3) // ', A WHOLE NUMBER'
      END IF
      CALL CMTRIM(WHERE, L1)
      CALL CMTRIM(FMT, LF)
      IF (IERR .EQ. 1) THEN
         MSG = WHERE(1:L1) // ': ''' // CARD(IECOL:IECOL) //
     1         ''' IS NOT PART OF A NUMBER; EXPECTED ' // FMT(1:LF)
      ELSE IF (IERR .EQ. 2) THEN
         MSG = WHERE(1:L1) // ': BLANK INSIDE THE NUMBER; WRITE IT '
     1         // 'WITHOUT BLANKS'
      ELSE IF (IERR .EQ. 3) THEN
         MSG = WHERE(1:L1) // ': MORE THAN 2 DECIMALS; THE MACHINE '
     1         // 'UNIT IS 0.01 MM'
      ELSE IF (IERR .EQ. 4) THEN
         IF (NDEC .GT. 0) THEN
            MSG = WHERE(1:L1) // ': NUMBER TOO LARGE; AT MOST '
     1            // '9999999.99'
         ELSE
            MSG = WHERE(1:L1) // ': NUMBER TOO LARGE; AT MOST '
     1            // '999999999'
         END IF
      ELSE IF (IERR .EQ. 5) THEN
         MSG = WHERE(1:L1) // ': A NUMBER WITHOUT A POINT MUST END IN '
     1         // 'COL ' // S2(1:L2) // '; RIGHT-JUSTIFY IT'
         IF (NDEC .GT. 0) MSG(L1+3:) = 'NO POINT, SO IT MUST END IN '
     1         // 'COL ' // S2(1:L2) // '; RIGHT-JUSTIFY IT OR ADD A '
     2         // 'POINT'
      ELSE IF (IERR .EQ. 6) THEN
         MSG = WHERE(1:L1) // ': NO DIGITS; EXPECTED ' // FMT(1:LF)
      ELSE
         MSG = WHERE(1:L1) // ': DECIMAL POINT IN A WHOLE-NUMBER FIELD;'
     1         // ' EXPECTED ' // FMT(1:LF)
      END IF
      CALL CMERR(PROG, ICRD, IECOL, MSG)
      RETURN
C     END OF CMFLD
      END
