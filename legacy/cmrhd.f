C=======================================================================
C     CMRHD  - I*A/N ROUNDED TO THE NEAREST WHOLE NUMBER, HALF DOWN
C                                                               (SHARED)
C     SOURCE:  SEED 004, THE TABLE OF 98132, 87647 IN 10 FRAMES (ITS
C              5TH FRAME TAKES 8764, SO 43823.5 WAS ROUNDED DOWN).
C     I, IA, N (INPUT) INTEGER  0 .LE. I .LE. N, IA .GE. 0, N .GE. 1;
C                               I*IA IS FORMED IN DOUBLE PRECISION,
C                               EXACT BELOW 2**53
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      INTEGER FUNCTION CMRHD(I, IA, N)
      IMPLICIT NONE
      INTEGER I, IA, N
C     ---- LOCAL -------------------------------------------------------
      DOUBLE PRECISION P, Q, R
C
      P = DBLE(I) * DBLE(IA)
      Q = AINT(P / N)
      R = P - Q * N
      IF (R .LT. 0.0D0) THEN
         Q = Q - 1.0D0
         R = R + N
      ELSE IF (R .GE. N) THEN
         Q = Q + 1.0D0
         R = R - N
      END IF
      IF (2.0D0 * R .GT. N) Q = Q + 1.0D0
      CMRHD = NINT(Q)
      RETURN
C     END OF CMRHD
      END
