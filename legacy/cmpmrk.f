C=======================================================================
C     CMPMRK - MARK ONE POINT ON THE CONTROL PLOT               (SHARED)
C     SOURCE:  RECONSTRUCTED.
C     GRID    (IN/OUT) CHARACTER*(*)     THE PLOT, NR LINES OF NC
C     NC, NR  (INPUT)  INTEGER           ITS COLUMNS AND LINES
C     CW, CH  (INPUT)  DOUBLE PRECISION  WIDTH AND HEIGHT OF A PRINT
C                                        POSITION, 0.01 MM
C     X, Y    (INPUT)  DOUBLE PRECISION  THE POINT, FROM THE START
C     CH1     (INPUT)  CHARACTER*1       THE MARK
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMPMRK(GRID, NC, NR, CW, CH, X, Y, CH1)
      IMPLICIT NONE
      INTEGER NC, NR
      CHARACTER*(*) GRID(NR)
      DOUBLE PRECISION CW, CH, X, Y
      CHARACTER*1 CH1
C     ---- /CMSTA/ WHAT THE SIMULATED MACHINE DID WITH EACH TAPE -------
      DOUBLE PRECISION DRAWN(3), TRAVL(3), RTIME(3), BBOX(4), PWIN(4)
      INTEGER NFRT(3), NROWT(3), IENDX, IENDY, IENDT
      COMMON /CMSTA/ DRAWN, TRAVL, RTIME, BBOX, PWIN, NFRT, NROWT,
     1               IENDX, IENDY, IENDT
      SAVE /CMSTA/
C     ---- LOCAL -------------------------------------------------------
      INTEGER IC, IR
C
      IC = INT((X - PWIN(1)) / CW) + 1
      IR = INT((PWIN(4) - Y) / CH) + 1
      IF (X .LT. PWIN(1) .OR. Y .GT. PWIN(4)) RETURN
      IF (IC .LT. 1 .OR. IC .GT. NC .OR. IR .LT. 1 .OR. IR .GT. NR)
     1   RETURN
      GRID(IR)(IC:IC) = CH1
      RETURN
C     END OF CMPMRK
      END
