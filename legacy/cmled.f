C=======================================================================
C     CMLED  - THE END AT A PLACE OF CMLK3'S CYCLE OF ENDS   (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMLK3), THE INVERSE OF CMLPS.
C     IP      (INPUT)  INTEGER  A PLACE, 0..2*NITM+1
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      INTEGER FUNCTION CMLED(IP)
      IMPLICIT NONE
      INTEGER IP
C     ---- /CMITM/ THE ITEMS OF A TAPE AND THE TOUR THROUGH THEM -------
      INTEGER MXITM
      PARAMETER (MXITM = 300000)
      INTEGER NITM, IKND(MXITM), IREF(MXITM), IEX(MXITM), IEY(MXITM),
     1        IXX(MXITM), IXY(MXITM), ITOUR(MXITM), IPOS(MXITM),
     2        IORI(MXITM), NJOB
      COMMON /CMITM/ NITM, IKND, IREF, IEX, IEY, IXX, IXY, ITOUR, IPOS,
     1               IORI, NJOB
      SAVE /CMITM/
C     ---- LOCAL -------------------------------------------------------
      INTEGER M
C
      IF (IP .EQ. 0) THEN
         CMLED = 2 * NITM + 1
      ELSE IF (IP .EQ. 2 * NITM + 1) THEN
         CMLED = 2 * NITM + 2
      ELSE IF (MOD(IP, 2) .EQ. 1) THEN
         M = ITOUR((IP + 1) / 2)
         CMLED = 2 * M - 1 + IORI(M)
      ELSE
         M = ITOUR(IP / 2)
         CMLED = 2 * M - IORI(M)
      END IF
      RETURN
C     END OF CMLED
      END
