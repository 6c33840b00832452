C=======================================================================
C     CMTLEN - THE LENGTH OF THE TOUR AS IT STANDS              (SHARED)
C     SOURCE:  RECONSTRUCTED. THE MOVES BETWEEN ITEMS WITH THE TOOL
C              RAISED, FROM WHERE THE TOUR STARTS THROUGH EVERY ITEM TO
C              THE START POINT (CMEND'S PLACES 0 TO NITM+1); WHAT IS
C              DRAWN INSIDE AN ITEM DOES NOT DEPEND ON THE ORDER.
C     RESULT  THE LENGTH, 0.01 MM
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      DOUBLE PRECISION FUNCTION CMTLEN()
      IMPLICIT NONE
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
      INTEGER IP, IX1, IY1, IX2, IY2
C
      CMTLEN = 0.0D0
      DO 10 IP = 0, NITM
         CALL CMEND(IP, 1, IX1, IY1)
         CALL CMEND(IP + 1, 2, IX2, IY2)
         CMTLEN = CMTLEN + SQRT((DBLE(IX1) - IX2)**2 +
     1                          (DBLE(IY1) - IY2)**2)
   10 CONTINUE
      RETURN
C     END OF CMTLEN
      END
