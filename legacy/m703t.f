C=======================================================================
C     M703T  - THE FRAMES OF A PAD TAPE                        (M703T)
C     SOURCE:  REPORT: P/L "DLYA OBRABOTKI MALYKH KONTAKTNYKH
C              PLOSHCHADOK" AND "... BOL'SHIKH ..." (THE SMALL-PAD AND
C              LARGE-PAD TAPES); DOCS/RECONSTRUCTION.MD.
C     THE M FRAMES OF THE TAPE COME FIRST, IN DECK ORDER, FROM THE
C     START POINT, EXACTLY AS PUNCHED ON THE CARDS; THEN THE PADS.
C     IU      (INPUT)  INTEGER  1 = SMALL PADS, 2 = LARGE PADS
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE M703T(IU)
      IMPLICIT NONE
      INTEGER IU
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
         IF (MMTAP(I) .EQ. IU) CALL CMFADD(MMX(I), MMY(I), MMDX(I),
     1      MMDY(I), MMCYC(I), MMK(I), MMCRD(I), 31)
   10 CONTINUE
      CALL MTPADS(IU)
      RETURN
C     END OF M703T
      END
