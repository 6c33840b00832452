C=======================================================================
C     CMGPT  - THE POINT OF AN END OF AN ITEM                   (SHARED)
C     SOURCE:  RECONSTRUCTED. END 2I-1 IS WHERE ITEM I IS ENTERED WHEN
C              DRAWN FORWARD, END 2I WHERE IT IS LEFT (CMTOUR); READ
C              FROM THE ITEM ITSELF, NOT FROM KQX, KQY (CMGRDY USES
C              THOSE FOR THE CHAINS' ENDS MEANWHILE).
C     IE      (INPUT)  INTEGER  THE END, 1..2*NITM
C     IX, IY  (OUTPUT) INTEGER  ITS POINT, 0.01 MM
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMGPT(IE, IX, IY)
      IMPLICIT NONE
      INTEGER IE, IX, IY
C     ---- /CMITM/ THE ITEMS OF A TAPE AND THE TOUR THROUGH THEM -------
      INTEGER MXITM
      PARAMETER (MXITM = 300000)
      INTEGER NITM, IKND(MXITM), IREF(MXITM), IEX(MXITM), IEY(MXITM),
     1        IXX(MXITM), IXY(MXITM), ITOUR(MXITM), IPOS(MXITM),
     2        IORI(MXITM)
      COMMON /CMITM/ NITM, IKND, IREF, IEX, IEY, IXX, IXY, ITOUR, IPOS,
     1               IORI
      SAVE /CMITM/
C     ---- LOCAL -------------------------------------------------------
      INTEGER M
C
      M = (IE + 1) / 2
      IF (MOD(IE, 2) .EQ. 1) THEN
         IX = IEX(M)
         IY = IEY(M)
      ELSE
         IX = IXX(M)
         IY = IXY(M)
      END IF
      RETURN
C     END OF CMGPT
      END
