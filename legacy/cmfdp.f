C=======================================================================
C     CMFDP  - A LENGTH OR A TIME AS TEXT WITH TWO DECIMALS   (SHARED)
C     SOURCE:  RECONSTRUCTED. THE LISTING'S STATISTICS (CMSTAT) ARE
C              DOUBLE PRECISION SUMS. AN F EDIT DESCRIPTOR MAY PRINT
C              0.70 AS ' .70' OR AS '0.70' (THE OPTIONAL ZERO OF
C              X3.9-1978 13.5.9.2.1): TWO PROCESSORS WOULD PRINT TWO
C              LISTINGS. THIS ROUTINE ALWAYS WRITES THE ZERO, AND
C              ROUNDS WITH ONE ADDITION AND ONE TRUNCATION, WHICH
C              EVERY PROCESSOR DOES ALIKE (NINT IS LEFT TO THE
C              PROCESSOR'S LIBRARY).
C     X       (INPUT)  DOUBLE PRECISION  THE VALUE
C     STR     (OUTPUT) CHARACTER  THE VALUE RIGHT-JUSTIFIED, E.G.
C                                 '      0.70'; ALL '*' WHEN IT DOES
C                                 NOT FIT, AS THE F EDITING DOES
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMFDP(X, STR)
      IMPLICIT NONE
      DOUBLE PRECISION X
      CHARACTER*(*) STR
C     ---- LOCAL -------------------------------------------------------
      CHARACTER*24 BUF
      CHARACTER*10 DIGS
      DOUBLE PRECISION A, HI, R
      INTEGER IHI, NR, K, I, L, NDIG
      DATA DIGS / '0123456789' /
C
C     THE VALUE IS SPLIT INTO UNITS OF 10 000 (HI) AND THE REST IN
C     HUNDREDTHS (NR, AT MOST 1 000 000), SO THAT NO INTEGER OVERFLOWS
C     BEFORE THE WIDTH OF THE FIELD IS EXCEEDED
      A = ABS(X)
      HI = AINT(A / 1.0D4)
      R = A - HI * 1.0D4
      IF (R .LT. 0.0D0) R = 0.0D0
      NR = INT(R * 100.0D0 + 0.5D0)
      IF (NR .GE. 1000000) THEN
         NR = NR - 1000000
         HI = HI + 1.0D0
      END IF
      IF (HI .GE. 1.0D9) GOTO 90
      IHI = INT(HI)
C     THE DIGITS FROM THE RIGHT: TWO DECIMALS, THE POINT, THEN THE
C     WHOLE PART (AT LEAST ONE DIGIT; FOUR WHEN A HIGH PART FOLLOWS)
      BUF = ' '
      K = LEN(BUF)
      BUF(K:K) = DIGS(MOD(NR, 10)+1:MOD(NR, 10)+1)
      NR = NR / 10
      BUF(K-1:K-1) = DIGS(MOD(NR, 10)+1:MOD(NR, 10)+1)
      NR = NR / 10
      BUF(K-2:K-2) = '.'
      K = K - 3
      NDIG = 0
   10 CONTINUE
      BUF(K:K) = DIGS(MOD(NR, 10)+1:MOD(NR, 10)+1)
      NR = NR / 10
      K = K - 1
      NDIG = NDIG + 1
      IF (NR .NE. 0 .OR. (IHI .GT. 0 .AND. NDIG .LT. 4)) GOTO 10
   20 CONTINUE
      IF (IHI .GT. 0) THEN
         BUF(K:K) = DIGS(MOD(IHI, 10)+1:MOD(IHI, 10)+1)
         IHI = IHI / 10
         K = K - 1
         GOTO 20
      END IF
      IF (X .LT. 0.0D0 .AND. BUF(K+1:) .NE. '0.00') THEN
         BUF(K:K) = '-'
         K = K - 1
      END IF
C     RIGHT-JUSTIFY INTO STR
      L = LEN(BUF) - K
      IF (L .GT. LEN(STR)) GOTO 90
      STR = ' '
      STR(LEN(STR)-L+1:) = BUF(K+1:)
      RETURN
C     THE VALUE DOES NOT FIT: ASTERISKS, AS THE F EDITING WRITES THEM
   90 CONTINUE
      DO 95 I = 1, LEN(STR)
         STR(I:I) = '*'
   95 CONTINUE
      RETURN
C     END OF CMFDP
      END
