C=======================================================================
C     CMFMM  - HUNDREDTHS OF A MILLIMETRE AS TEXT 'NNN.NN'    (SHARED)
C     SOURCE:  RECONSTRUCTED. EVERY LENGTH IS HELD AS AN INTEGER IN
C              THE TAPE UNIT 0.01 MM (THE REPORT); THIS PRINTS ONE.
C     IVAL    (INPUT)  INTEGER    VALUE IN 0.01 MM
C     STR     (OUTPUT) CHARACTER  E.G. '12.50', '-0.05', '0.00'
C     LSTR    (OUTPUT) INTEGER    NUMBER OF CHARACTERS USED
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMFMM(IVAL, STR, LSTR)
      IMPLICIT NONE
      INTEGER IVAL, LSTR
      CHARACTER*(*) STR
C     ---- LOCAL -------------------------------------------------------
      CHARACTER*14 BUF
      INTEGER IW, IFR, L, LW
C
      IW = IVAL / 100
      IFR = ABS(MOD(IVAL, 100))
      BUF = ' '
      L = 0
      IF (IVAL .LT. 0 .AND. IW .EQ. 0) THEN
         BUF(1:1) = '-'
         L = 1
      END IF
      CALL CMITOA(IW, BUF(L+1:), LW)
      L = L + LW
      BUF(L+1:L+1) = '.'
      BUF(L+2:L+2) = CHAR(ICHAR('0') + IFR / 10)
      BUF(L+3:L+3) = CHAR(ICHAR('0') + MOD(IFR, 10))
      L = L + 3
      STR = BUF(1:L)
      LSTR = MIN(L, LEN(STR))
      RETURN
C     END OF CMFMM
      END
