C=======================================================================
C     CMNUM  - READ ONE NUMERIC FIELD OF A CARD, EXACTLY        (SHARED)
C     SOURCE:  RECONSTRUCTED, DOCS/CARDS.MD: FIELDS ARE READ "THE
C              FORTRAN WAY" (FW.D: WITHOUT A POINT THE LAST D DIGITS ARE
C              DECIMALS), BUT IN INTEGER ARITHMETIC SO THAT 12.50 MM IS
C              EXACTLY 1250 HUNDREDTHS, AND STRICTER THAN FORMAT READING
C              WHERE FORTRAN IV AND FORTRAN 77 DISAGREE:
C              - LEADING AND TRAILING BLANKS ARE IGNORED; A BLANK
C                BETWEEN DIGITS IS AN ERROR (BN WOULD JOIN THE DIGITS,
C                BZ WOULD READ IT AS ZERO);
C              - A NUMBER WITHOUT A DECIMAL POINT MUST BE RIGHT-
C                JUSTIFIED (UNDER BZ TRAILING BLANKS ARE ZEROS);
C              - DIGITS PAST THE D-TH DECIMAL MUST BE ZERO: THE MACHINE
C                UNIT IS 0.01 MM AND NOTHING IS ROUNDED AWAY SILENTLY.
C     CARD    (INPUT)  CHARACTER  THE CARD IMAGE
C     IC1,IC2 (INPUT)  INTEGER    FIRST AND LAST COLUMN OF THE FIELD
C     NDEC    (INPUT)  INTEGER    D: 2 FOR F10.2 AND F8.2, 0 FOR IW
C     IVAL    (OUTPUT) INTEGER    VALUE IN UNITS OF 10**(-NDEC), 0 IF
C                                 BLANK; ABS(IVAL) .LE. 999999999
C     LBLANK  (OUTPUT) INTEGER    1 IF THE FIELD IS BLANK, ELSE 0
C     IERR    (OUTPUT) INTEGER    0 = DONE; 1 = CHARACTER THAT IS NOT
C                                 PART OF A NUMBER; 2 = BLANK INSIDE;
C                                 3 = NON-ZERO DIGIT PAST D DECIMALS;
C                                 4 = TOO LARGE; 5 = NOT RIGHT-
C                                 JUSTIFIED;
C                                 6 = NO DIGITS; 7 = POINT IN AN
C                                 INTEGER FIELD
C     IECOL   (OUTPUT) INTEGER    COLUMN OF THE FAULT (IERR .NE. 0)
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMNUM(CARD, IC1, IC2, NDEC, IVAL, LBLANK, IERR, IECOL)
      IMPLICIT NONE
      CHARACTER*(*) CARD
      INTEGER IC1, IC2, NDEC, IVAL, LBLANK, IERR, IECOL
C     ---- LOCAL -------------------------------------------------------
      INTEGER MAXV, MAXV10
      PARAMETER (MAXV = 999999999, MAXV10 = 99999999)
      INTEGER IA, IB, I, ID, IACC, NFRAC, NDIG, LPOINT, ISIGN, K
      CHARACTER*1 CH, BLANK
C     A BLANK AS A VARIABLE, NOT A CONSTANT, AND A DIGIT'S VALUE FROM
C     ICHAR AS CMPNUM TAKES IT: GFORTRAN TURNS A COMPARISON WITH A BLANK
C     CONSTANT INTO A CALL OF ITS LEN_TRIM, AND INDEX INTO A CALL, FOR
C     EVERY COLUMN OF EVERY NUMBER (3 PER CENT OF THE RUN OF A DECK OF
C     100 000 PADS WENT TO THOSE CALLS)
      DATA BLANK /' '/
C
      IVAL = 0
      LBLANK = 0
      IERR = 0
      IECOL = 0
C     ---- FIND THE FIRST AND LAST NON-BLANK COLUMN --------------------
      IA = 0
      IB = 0
      DO 10 I = IC1, IC2
         IF (CARD(I:I) .NE. BLANK) THEN
            IF (IA .EQ. 0) IA = I
            IB = I
         END IF
   10 CONTINUE
      IF (IA .EQ. 0) THEN
         LBLANK = 1
         RETURN
      END IF
C     ---- SCAN: SIGN, DIGITS, POINT, DIGITS ---------------------------
      IACC = 0
      NFRAC = 0
      NDIG = 0
      LPOINT = 0
      ISIGN = 1
      DO 20 I = IA, IB
         CH = CARD(I:I)
         ID = ICHAR(CH) - ICHAR('0')
         IF (ID .GT. 9) ID = -1
         IF (ID .GE. 0) THEN
            NDIG = NDIG + 1
            IF (LPOINT .EQ. 1) THEN
               NFRAC = NFRAC + 1
               IF (NFRAC .GT. NDEC) THEN
                  IF (ID .NE. 0) THEN
                     IERR = 3
                     IECOL = I
                     RETURN
                  END IF
                  GOTO 20
               END IF
            END IF
            IF (IACC .GT. (MAXV - ID) / 10) THEN
               IERR = 4
               IECOL = IA
               RETURN
            END IF
            IACC = 10 * IACC + ID
         ELSE IF ((CH .EQ. '+' .OR. CH .EQ. '-') .AND. I .EQ. IA) THEN
            IF (CH .EQ. '-') ISIGN = -1
         ELSE IF (CH .EQ. '.' .AND. LPOINT .EQ. 0) THEN
            IF (NDEC .EQ. 0) THEN
               IERR = 7
               IECOL = I
               RETURN
            END IF
            LPOINT = 1
         ELSE IF (CH .EQ. ' ') THEN
            IERR = 2
            IECOL = I
            RETURN
         ELSE
            IERR = 1
            IECOL = I
            RETURN
         END IF
   20 CONTINUE
      IF (NDIG .EQ. 0) THEN
         IERR = 6
         IECOL = IA
         RETURN
      END IF
      IF (LPOINT .EQ. 0) THEN
C        NO POINT: THE LAST NDEC DIGITS ARE THE DECIMALS, AS FW.D
         IF (IB .NE. IC2) THEN
            IERR = 5
            IECOL = IB + 1
            RETURN
         END IF
      ELSE
C        POINT GIVEN: SCALE THE DIGITS READ UP TO NDEC DECIMALS
         DO 30 K = MIN(NFRAC, NDEC) + 1, NDEC
            IF (IACC .GT. MAXV10) THEN
               IERR = 4
               IECOL = IA
               RETURN
            END IF
            IACC = 10 * IACC
   30    CONTINUE
      END IF
      IVAL = ISIGN * IACC
      RETURN
C     END OF CMNUM
      END
