C=======================================================================
C     CMLPS  - THE PLACE OF AN END IN CMLK3'S CYCLE OF ENDS  (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMLK3). PLACE 0 IS THE TOOL'S START,
C              2P-1 THE ENTRY AND 2P THE EXIT OF THE ITEM AT PLACE P OF
C              THE TOUR, 2*NITM+1 THE START POINT.
C     IE      (INPUT)  INTEGER  AN END (1..2*NITM), 2*NITM+1 THE TOOL'S
C                               START OR 2*NITM+2 THE START POINT
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      INTEGER FUNCTION CMLPS(IE)
      IMPLICIT NONE
      INTEGER IE
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
      IF (IE .GT. 2 * NITM) THEN
         CMLPS = 0
         IF (IE .EQ. 2 * NITM + 2) CMLPS = 2 * NITM + 1
         RETURN
      END IF
      M = (IE + 1) / 2
      IF (IE .EQ. 2 * M - 1 + IORI(M)) THEN
         CMLPS = 2 * IPOS(M) - 1
      ELSE
         CMLPS = 2 * IPOS(M)
      END IF
      RETURN
C     END OF CMLPS
      END
