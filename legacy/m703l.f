C=======================================================================
C     M703L  - THE FRAMES OF THE CONDUCTOR TAPE                (M703L)
C     SOURCE:  REPORT: P/L "DLYA OBRABOTKI PROVODNIKOV" (THE CONDUCTOR
C              TAPE); M703L WAS WRITTEN BY V.S. PILIPCHENKO;
C              DOCS/RECONSTRUCTION.MD.
C     THE M FRAMES OF TAPE L COME FIRST, IN DECK ORDER, FROM THE START
C     POINT, EXACTLY AS PUNCHED ON THE CARDS; THEN THE CONDUCTORS,
C     CIRCLES AND ARCS.
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE M703L
      IMPLICIT NONE
C     ---- /CMMAN/ MANUAL FRAMES OF M CARDS, IN DECK ORDER -------------
      INTEGER MXMAN
      PARAMETER (MXMAN = 20000)
      INTEGER NMAN, MMTAP(MXMAN), MMX(MXMAN), MMY(MXMAN), MMDX(MXMAN),
     1        MMDY(MXMAN), MMCYC(MXMAN), MMK(MXMAN), MMCRD(MXMAN)
      COMMON /CMMAN/ NMAN, MMTAP, MMX, MMY, MMDX, MMDY, MMCYC, MMK,
     1               MMCRD
      SAVE /CMMAN/
C     ---- LOCAL -------------------------------------------------------
      INTEGER I
C
      DO 10 I = 1, MIN(NMAN, MXMAN)
         IF (MMTAP(I) .EQ. 3) CALL CMFADD(MMX(I), MMY(I), MMDX(I),
     1      MMDY(I), MMCYC(I), MMK(I), MMCRD(I), 31)
   10 CONTINUE
      CALL MLCOND
      RETURN
C     END OF M703L
      END
