C=======================================================================
C     CMSAME - TWO NAMES ARE ONE, WHATEVER THEIR CASE        (SHARED)
C     SOURCE:  RECONSTRUCTED. THE BESM-6 HAD ONE CASE; A FILE SYSTEM OF
C              TODAY MAY HAVE TWO (LINUX) OR ONE (MACOS, WINDOWS), SO
C              THAT NAMES 'ABC' AND 'abc' WOULD NAME ONE FILE THERE.
C              TENZOR TAKES SUCH NAMES FOR THE SAME NAME EVERYWHERE.
C     A, B    (INPUT)  CHARACTER  THE NAMES (TRAILING BLANKS IGNORED)
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      LOGICAL FUNCTION CMSAME(A, B)
      IMPLICIT NONE
      CHARACTER*(*) A, B
C     ---- LOCAL -------------------------------------------------------
      CHARACTER*26 UP, LOW
      CHARACTER*1 CA, CB
      INTEGER I, K, N
      DATA UP / 'ABCDEFGHIJKLMNOPQRSTUVWXYZ' /
      DATA LOW / 'abcdefghijklmnopqrstuvwxyz' /
C
      CMSAME = .FALSE.
      N = MAX(LEN(A), LEN(B))
      DO 10 I = 1, N
         CA = ' '
         CB = ' '
         IF (I .LE. LEN(A)) CA = A(I:I)
         IF (I .LE. LEN(B)) CB = B(I:I)
         K = INDEX(LOW, CA)
         IF (K .GT. 0) CA = UP(K:K)
         K = INDEX(LOW, CB)
         IF (K .GT. 0) CB = UP(K:K)
         IF (CA .NE. CB) RETURN
   10 CONTINUE
      CMSAME = .TRUE.
      RETURN
C     END OF CMSAME
      END
