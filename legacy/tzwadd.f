C=======================================================================
C     TZWADD - WIDEN THE PLOT WINDOW TO HOLD A DISC             (TENZOR)
C     SOURCE:  RECONSTRUCTED.
C     X, Y    (INPUT)  DOUBLE PRECISION  THE CENTRE, 0.01 MM
C     R       (INPUT)  DOUBLE PRECISION  THE RADIUS, 0.01 MM
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE TZWADD(X, Y, R)
      IMPLICIT NONE
      DOUBLE PRECISION X, Y, R
C     ---- /CMSTA/ WHAT THE SIMULATED MACHINE DID WITH EACH TAPE -------
      DOUBLE PRECISION DRAWN(3), TRAVL(3), RTIME(3), BBOX(4), PWIN(4)
      INTEGER NFRT(3), NROWT(3), IENDX, IENDY, IENDT
      COMMON /CMSTA/ DRAWN, TRAVL, RTIME, BBOX, PWIN, NFRT, NROWT,
     1               IENDX, IENDY, IENDT
      SAVE /CMSTA/
C
      PWIN(1) = MIN(PWIN(1), X - R)
      PWIN(2) = MAX(PWIN(2), X + R)
      PWIN(3) = MIN(PWIN(3), Y - R)
      PWIN(4) = MAX(PWIN(4), Y + R)
      RETURN
C     END OF TZWADD
      END
