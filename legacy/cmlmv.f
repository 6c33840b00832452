C=======================================================================
C     CMLMV  - MAKE ONE OF CMLK3'S MOVES BY REVERSALS      (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMLK3, CMLCL3 FOR THE TYPES).
C     ITYP    (INPUT)  INTEGER  1..4 A 3-OPT MOVE, 5 A 2-OPT MOVE
C     IBA, IBB, IBC (INPUT) INTEGER  THE PLACES AFTER WHICH THE MOVES
C                               GO OUT (IBC UNUSED FOR 2-OPT)
C     KR1, KR2, NREV (IN/OUT) THE REVERSALS MADE, ADDED TO THE LIST
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMLMV(ITYP, IBA, IBB, IBC, KR1, KR2, NREV)
      IMPLICIT NONE
      INTEGER ITYP, IBA, IBB, IBC, KR1(*), KR2(*), NREV
C     ---- LOCAL -------------------------------------------------------
      INTEGER I1(3), I2(3), N, I, K
C
      K = IBA + IBC - IBB
      IF (ITYP .EQ. 5) THEN
         N = 1
         I1(1) = IBA + 1
         I2(1) = IBB
      ELSE IF (ITYP .EQ. 1) THEN
         N = 2
         I1(1) = IBA + 1
         I2(1) = IBB
         I1(2) = IBB + 1
         I2(2) = IBC
      ELSE
         N = 1
         I1(1) = IBA + 1
         I2(1) = IBC
         IF (ITYP .EQ. 2 .OR. ITYP .EQ. 4) THEN
            N = N + 1
            I1(N) = IBA + 1
            I2(N) = K
         END IF
         IF (ITYP .EQ. 2 .OR. ITYP .EQ. 3) THEN
            N = N + 1
            I1(N) = K + 1
            I2(N) = IBC
         END IF
      END IF
      DO 10 I = 1, N
         CALL CMTREV(I1(I), I2(I))
         NREV = NREV + 1
         KR1(NREV) = I1(I)
         KR2(NREV) = I2(I)
   10 CONTINUE
      RETURN
C     END OF CMLMV
      END
