C=======================================================================
C     CMLXY  - THE POINT OF AN END OF CMLK3'S CYCLE OF ENDS  (SHARED)
C     SOURCE:  RECONSTRUCTED (SEE CMLK3).
C     IE      (INPUT)  INTEGER  AN END, AS FOR CMLPS
C     IX, IY  (OUTPUT) INTEGER  ITS POINT
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMLXY(IE, IX, IY)
      IMPLICIT NONE
      INTEGER IE, IX, IY
C     ---- /CMITM/ THE ITEMS OF A TAPE AND THE TOUR THROUGH THEM -------
      INTEGER MXITM
      PARAMETER (MXITM = 300000)
      INTEGER NITM, IKND(MXITM), IREF(MXITM), IEX(MXITM), IEY(MXITM),
     1        IXX(MXITM), IXY(MXITM), ITOUR(MXITM), IPOS(MXITM),
     2        IORI(MXITM), NJOB
      COMMON /CMITM/ NITM, IKND, IREF, IEX, IEY, IXX, IXY, ITOUR, IPOS,
     1               IORI, NJOB
      SAVE /CMITM/
C     ---- /CMTWK/ WORK SPACE OF THE TOUR: GRID, NEIGHBOURS, QUEUE -----
      INTEGER MXPT, MXCEL, MXNB
      PARAMETER (MXPT = 2 * MXITM, MXCEL = 2 * MXITM, MXNB = 16)
      INTEGER NGX, NGY, KGX0, KGY0, KGCS, KDSX, KDSY, KDTX, KDTY,
     1        KQHD, KQN, KWORK, KWMAX,
     2        KQX(MXPT), KQY(MXPT), KCST(MXCEL + 1), KCCN(MXCEL),
     3        KCEL(MXPT), KSLT(MXPT), KNB(MXNB, MXPT), KQUE(MXITM),
     4        LQUE(MXITM)
      COMMON /CMTWK/ NGX, NGY, KGX0, KGY0, KGCS, KDSX, KDSY, KDTX, KDTY,
     1               KQHD, KQN, KWORK, KWMAX, KQX, KQY, KCST, KCCN,
     2               KCEL, KSLT, KNB, KQUE, LQUE
      SAVE /CMTWK/
C
      IF (IE .LE. 2 * NITM) THEN
         IX = KQX(IE)
         IY = KQY(IE)
      ELSE IF (IE .EQ. 2 * NITM + 1) THEN
         IX = KDSX
         IY = KDSY
      ELSE
         IX = KDTX
         IY = KDTY
      END IF
      RETURN
C     END OF CMLXY
      END
