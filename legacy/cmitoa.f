C=======================================================================
C     CMITOA - AN INTEGER AS LEFT-JUSTIFIED DECIMAL TEXT      (SHARED)
C     SOURCE:  RECONSTRUCTED. THE LISTING AND THE FRAME TEXT NEED
C              NUMBERS WITHOUT LEADING BLANKS.
C     IVAL    (INPUT)  INTEGER    THE VALUE, ANY SIGN
C     STR     (OUTPUT) CHARACTER  THE DIGITS, '-' FIRST IF NEGATIVE,
C                                 BLANK-FILLED ON THE RIGHT
C     LSTR    (OUTPUT) INTEGER    NUMBER OF CHARACTERS USED
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMITOA(IVAL, STR, LSTR)
      IMPLICIT NONE
      INTEGER IVAL, LSTR
      CHARACTER*(*) STR
C     ---- LOCAL -------------------------------------------------------
      CHARACTER*12 BUF
      CHARACTER*10 DIGS
      INTEGER N, I, K, D
      DATA DIGS / '0123456789' /
C
      N = IVAL
      K = 12
      BUF = ' '
C     BUILD THE DIGITS FROM THE RIGHT; WORK WITH A NON-POSITIVE VALUE
C     SO THAT THE MOST NEGATIVE INTEGER NEEDS NO SPECIAL CASE
      IF (N .GT. 0) N = -N
   10 CONTINUE
      D = -MOD(N, 10)
      BUF(K:K) = DIGS(D+1:D+1)
      K = K - 1
      N = N / 10
      IF (N .NE. 0) GOTO 10
      IF (IVAL .LT. 0) THEN
         BUF(K:K) = '-'
         K = K - 1
      END IF
      STR = ' '
      LSTR = 12 - K
      DO 20 I = 1, LSTR
         IF (I .LE. LEN(STR)) STR(I:I) = BUF(K+I:K+I)
   20 CONTINUE
      IF (LSTR .GT. LEN(STR)) LSTR = LEN(STR)
      RETURN
C     END OF CMITOA
      END
