C=======================================================================
C     CMGDEL - TAKE A USED END OFF THE GRID                     (SHARED)
C     SOURCE:  RECONSTRUCTED. THE LAST LIVE END OF ITS CELL TAKES ITS
C              PLACE, SO THE LIVE ENDS OF A CELL STAY TOGETHER.
C     IP      (INPUT)  INTEGER  THE END, LIVE
C     CHANGES: SEE THE HISTORY OF THE REPOSITORY (GIT LOG)
C=======================================================================
      SUBROUTINE CMGDEL(IP)
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
C     ---- LOCAL -------------------------------------------------------
      INTEGER IC, IS, LAST, IQ
C
      CALL CMCELL(KQX(IP), KQY(IP), IC)
      IS = KSLT(IP)
      LAST = KCST(IC) + KCCN(IC) - 1
      IQ = KCEL(LAST)
      KCEL(IS) = IQ
      KSLT(IQ) = IS
      KCEL(LAST) = IP
      KSLT(IP) = LAST
      KCCN(IC) = KCCN(IC) - 1
      RETURN
C     END OF CMGDEL
      END
