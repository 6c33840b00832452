C=======================================================================
C     CMKINS - INSERT INTO A SHORT LIST OF THE NEAREST         (SHARED)
C     SOURCE:  RECONSTRUCTED.
C     NBI,NBD (IN/OUT) THE ENDS AND THEIR SQUARED DISTANCES, NEAREST
C                      FIRST (TIES: SMALLER END FIRST)
C     N       (IN/OUT) INTEGER  HOW MANY ARE LISTED, AT MOST MXN
C     MXN     (INPUT)  INTEGER  THE LENGTH OF THE LIST
C     IQ, D   (INPUT)  THE CANDIDATE AND ITS SQUARED DISTANCE
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMKINS(NBI, NBD, N, MXN, IQ, D)
      IMPLICIT NONE
      INTEGER MXN, N, IQ, NBI(MXN)
      DOUBLE PRECISION D, NBD(MXN)
C     ---- LOCAL -------------------------------------------------------
      INTEGER J
C
      IF (N .EQ. MXN) THEN
         IF (D .GT. NBD(N) .OR. (D .EQ. NBD(N) .AND. IQ .GT. NBI(N)))
     1      RETURN
      ELSE
         N = N + 1
      END IF
      J = N
   10 CONTINUE
      IF (J .GT. 1) THEN
         IF (NBD(J-1) .GT. D .OR. (NBD(J-1) .EQ. D .AND.
     1       NBI(J-1) .GT. IQ)) THEN
            NBD(J) = NBD(J-1)
            NBI(J) = NBI(J-1)
            J = J - 1
            GOTO 10
         END IF
      END IF
      NBD(J) = D
      NBI(J) = IQ
      RETURN
C     END OF CMKINS
      END
